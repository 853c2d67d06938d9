"""What the SEAS tests (seasBP3.sh, seasBP5.sh) read back of faultOutput's rupture files."""
import os


def rows(path):
    """The numeric rows of a faultOutput file (comments and column lines skipped)."""
    return [[float(x) for x in line.split()] for line in open(path)
            if line[:1] not in "#xt" and line.strip()]


def eventsAndFiles(out):
    """global.dat's events, (onset, end): from the first row at or above log10 1e-3 m/s to the
    first below; and the rupture_<k>.dat files in out, in the order of k."""
    events, start = [], None
    for t, lv, _ in rows(os.path.join(out, "global.dat")):
        if start is None and lv >= -3:
            start = t
        elif start is not None and lv < -3:
            events.append((start, t))
            start = None
    files = sorted((f for f in os.listdir(out) if f.startswith("rupture_")),
                   key=lambda f: int(f[len("rupture_"):-len(".dat")]))
    return events, files
