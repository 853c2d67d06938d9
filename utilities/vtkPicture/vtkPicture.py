#!/usr/bin/python3
"""vtkPicture: a picture of a solved case's ParaView files, drawn by VTK itself (python3-vtk9),
without ParaView and without a screen: what a user sees on first opening the case in ParaView,
the faults in front.

It reads VTK/<case>.pvd (the time's .vtu and .vtp files, as frictionSolver writes them) and
draws, at one written time:
  * the body: its outer surface as a light wireframe (the split mesh's boundary edges), so the
    faults inside it show;
  * every fracture: in 3D its surface, in 2D its polyline (thickened), coloured by a point array
    of its .vtp (default slipMagnitude in 3D, slip in 2D), with a colour bar titled by the
    array and the time;
  * z up (3D; y up in 2D), the camera looking at the faults along their mean normal (-view
    normal, the default), or from the south-east above (-view iso), or from above (-view top).
Fractures whose array is absent are drawn grey. A NaN value (the solver writes none) is drawn in
the NaN colour.

Usage:
  vtkPicture -case DIR [-time T] [-array NAME] [-view normal|iso|top] [-size W,H]
             [-o out.png]
  -time   a written time (default: the last); its value as in the .pvd or the time folder
  -o      default <case>/postProcessing/vtk_<array>_<time>.png (written under a temporary
          name, then renamed: a failed run leaves no picture)
Prints one line: the file written, the time, the array and its range.

Rendering needs an X display; without one (a server, a test run) the script runs itself again
under xvfb-run (Debian package xvfb), which gives VTK a virtual one. Errors (no .pvd, an
unknown time or array, no display and no xvfb-run) go to stderr, exit 1.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET


class PictureError(Exception):
    pass


def collection(case):
    """(time value, [files relative to VTK/], [names]) per time of VTK/<name>.pvd."""
    vtk = os.path.join(case, "VTK")
    pvds = sorted(f for f in os.listdir(vtk) if f.endswith(".pvd")) if os.path.isdir(vtk) else []
    if not pvds:
        raise PictureError(f"{case}: no VTK/<case>.pvd (run frictionSolver with writeVTK yes)")
    if len(pvds) > 1:
        name = os.path.basename(os.path.abspath(case)) + ".pvd"
        if name not in pvds:
            raise PictureError(f"{vtk}: several collections ({' '.join(pvds)}), none named {name}")
        pvds = [name]
    times = {}
    order = []
    root = ET.parse(os.path.join(vtk, pvds[0])).getroot()
    for d in root.iter("DataSet"):
        t = d.get("timestep")
        if t not in times:
            times[t] = ([], [])
            order.append(t)
        times[t][0].append(d.get("file"))
        times[t][1].append(d.get("name") or "")
    if not order:
        raise PictureError(f"{os.path.join(vtk, pvds[0])}: no DataSet entries")
    return vtk, [(t, *times[t]) for t in order]


def pick(times, wanted):
    if wanted is None:
        return times[-1]
    for t in times:
        if math.isclose(float(t[0]), float(wanted), rel_tol=1e-9, abs_tol=1e-300):
            return t
    raise PictureError(f"-time {wanted}: not a written time (written: "
                       f"{' '.join(t[0] for t in times)})")


def render(args):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    case = args.case
    folder, times = collection(case)
    time, files, names = pick(times, args.time)
    mesh = [f for f in files if f.endswith(".vtu")]
    fractures = [(f, n) for f, n in zip(files, names) if f.endswith(".vtp")]
    if not mesh:
        raise PictureError(f"time {time}: the .pvd names no .vtu")

    errors = []

    def read(reader, path):
        reader.AddObserver(vtk.vtkCommand.ErrorEvent, lambda o, e: errors.append(path))
        reader.SetFileName(path)
        reader.Update()
        if errors:
            raise PictureError(f"{path}: VTK could not read it")
        return reader.GetOutput()

    body = read(vtk.vtkXMLUnstructuredGridReader(), os.path.join(folder, mesh[0]))
    bounds = body.GetBounds()
    is3d = bounds[5] - bounds[4] > 0
    array = args.array or ("slipMagnitude" if is3d else "slip")

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    # The body: its outer surface's edges (linear cells: P2 drawn by its corners).
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(body)
    edges = vtk.vtkFeatureEdges()
    edges.SetInputConnection(surface.GetOutputPort())
    edges.BoundaryEdgesOn()
    edges.FeatureEdgesOn()
    edges.ManifoldEdgesOff()
    edges.NonManifoldEdgesOff()
    edges.ColoringOff()
    bodyMapper = vtk.vtkPolyDataMapper()
    bodyMapper.SetInputConnection(edges.GetOutputPort())
    bodyMapper.ScalarVisibilityOff()
    bodyActor = vtk.vtkActor()
    bodyActor.SetMapper(bodyMapper)
    bodyActor.GetProperty().SetColor(0.45, 0.45, 0.45)
    renderer.AddActor(bodyActor)

    lo, hi, found, normals = math.inf, -math.inf, [], []
    faults = []
    for f, name in fractures:
        data = read(vtk.vtkXMLPolyDataReader(), os.path.join(folder, f))
        values = data.GetPointData().GetArray(array)
        if values is not None:
            v = vtk_to_numpy(values)
            v = v if v.ndim == 1 else (v ** 2).sum(axis=1) ** 0.5
            finite = v[v == v]
            if finite.size:
                lo, hi = min(lo, float(finite.min())), max(hi, float(finite.max()))
            found.append(name or f)
        n = data.GetPointData().GetArray("normal")
        if n is not None:
            normals.append(vtk_to_numpy(n).mean(axis=0))
        faults.append((data, values is not None))
    if fractures and not found:
        raise PictureError(f"-array {array}: no fracture's .vtp has it at time {time}")
    if lo > hi:
        lo, hi = 0.0, 1.0
    if lo == hi:
        lo, hi = lo - 0.5 * max(abs(lo), 1e-300), hi + 0.5 * max(abs(hi), 1e-300)

    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)  # blue (low) to red (high)
    lut.SetNanColor(0.2, 0.2, 0.2, 1.0)
    lut.SetTableRange(lo, hi)
    lut.Build()
    width = 0.004 * max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    for data, coloured in faults:
        source = data
        if not is3d:
            tube = vtk.vtkTubeFilter()
            tube.SetInputData(data)
            tube.SetRadius(width)
            tube.SetNumberOfSides(8)
            tube.Update()
            source = tube.GetOutput()
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputData(source)
        if coloured:
            source.GetPointData().SetActiveScalars(array)
            mapper.SetScalarModeToUsePointData()
            mapper.SetColorModeToMapScalars()
            mapper.SetLookupTable(lut)
            mapper.SetScalarRange(lo, hi)
            mapper.ScalarVisibilityOn()
            if source.GetPointData().GetArray(array).GetNumberOfComponents() > 1:
                mapper.GetLookupTable().SetVectorModeToMagnitude()
        else:
            mapper.ScalarVisibilityOff()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        if not coloured:
            actor.GetProperty().SetColor(0.7, 0.7, 0.7)
        renderer.AddActor(actor)

    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(f"{array}\nt = {time}")
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%-#8.3g")
    for prop in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        prop.SetColor(0, 0, 0)
        prop.ItalicOff()
        prop.ShadowOff()
    bar.SetPosition(0.02, 0.06)
    bar.SetWidth(0.96)
    bar.SetHeight(0.86)
    bar.SetBarRatio(0.3)
    bar.UnconstrainedFontSizeOn()
    bar.GetTitleTextProperty().SetFontSize(16)
    bar.GetLabelTextProperty().SetFontSize(14)
    # The scene on the left, the colour bar in a strip of its own on the right.
    renderer.SetViewport(0.0, 0.0, 0.78, 1.0)
    legend = vtk.vtkRenderer()
    legend.SetViewport(0.78, 0.0, 1.0, 1.0)
    legend.SetBackground(1, 1, 1)
    legend.AddActor2D(bar)

    camera = renderer.GetActiveCamera()
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    camera.SetFocalPoint(*centre)
    if not is3d or args.view == "top":
        camera.SetPosition(centre[0], centre[1], centre[2] + 1)
        camera.SetViewUp(0, 1, 0)
    elif args.view == "iso" or not normals:
        camera.SetPosition(centre[0] + 1, centre[1] - 1, centre[2] + 0.8)
        camera.SetViewUp(0, 0, 1)
    else:
        n = sum(normals) / len(normals)
        norm = math.sqrt(sum(c * c for c in n))
        n = [c / norm for c in n] if norm > 0 else [1, 0, 0]
        if abs(n[2]) > 0.999:  # a horizontal fault: seen from above, y up
            camera.SetPosition(centre[0], centre[1], centre[2] + 1)
            camera.SetViewUp(0, 1, 0)
        else:
            camera.SetPosition(centre[0] + n[0], centre[1] + n[1], centre[2] + n[2])
            camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.1)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*args.size)
    window.AddRenderer(renderer)
    window.AddRenderer(legend)
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.Update()
    out = args.o or os.path.join(case, "postProcessing", f"vtk_{array}_{time}.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    tmp = os.path.join(os.path.dirname(os.path.abspath(out)), "." + os.path.basename(out) + ".tmp.png")
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(tmp)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    if not os.path.isfile(tmp) or os.path.getsize(tmp) == 0:
        raise PictureError(f"{out}: VTK wrote no picture")
    os.replace(tmp, out)
    print(f"vtkPicture: wrote {out} (t = {time}, {array} from {lo:.4g} to {hi:.4g}"
          f"{'' if fractures else '; no fractures'})")


def main(argv):
    ap = argparse.ArgumentParser(prog="vtkPicture", description=__doc__.split("\n\n")[0])
    ap.add_argument("-case", required=True)
    ap.add_argument("-time")
    ap.add_argument("-array")
    ap.add_argument("-view", choices=("normal", "iso", "top"), default="normal")
    ap.add_argument("-size", default="1000,750")
    ap.add_argument("-o")
    args = ap.parse_args(argv)
    try:
        w, h = (int(v) for v in args.size.split(","))
        if not (16 <= w <= 8000 and 16 <= h <= 8000):
            raise ValueError
        args.size = (w, h)
    except ValueError:
        print(f"vtkPicture: error: -size: expected W,H in pixels (16 to 8000), got "
              f"'{args.size}'", file=sys.stderr)
        return 1
    if not os.environ.get("DISPLAY") and not os.environ.get("VTK_PICTURE_XVFB"):
        # No screen: once more under a virtual one.
        xvfb = shutil.which("xvfb-run")
        if not xvfb:
            print("vtkPicture: error: no X display (DISPLAY is unset) and no xvfb-run to make "
                  "one: install the Debian package xvfb", file=sys.stderr)
            return 1
        env = dict(os.environ, VTK_PICTURE_XVFB="1")
        return subprocess.call([xvfb, "-a", "-s", "-screen 0 1280x1024x24", sys.executable,
                                os.path.abspath(__file__)] + argv, env=env)
    try:
        render(args)
    except PictureError as e:
        print(f"vtkPicture: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
