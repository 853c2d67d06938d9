#!/usr/bin/env python3
"""Compare the fracture tables of case runs with a reference run (tests/regression/parallelRanks.sh).

Usage: parallelCompare.py [--tolerance T] REFERENCE_CASE RUN_CASE...

Every `<time>/fractures/<name>.dat` of the reference must exist in each run with the same rows,
the same `state` column, the same status on its `# status` line and the same comment lines that
mark where fractures meet (2D `# junction at ...`, 3D `# intersection ...`); each numeric column must
agree to 1e-9 of its scale in the reference table: tractions (sigmaN, tau..., residual, and a
fluid pressure's pressure, sigmaNEffective and deltaCFS) against
the largest traction of the table, slips and openings (slip..., opening) against the largest of
them, ST (a ratio like the friction coefficient) against max(largest ST, 1), the rest against
its own largest magnitude. A column's own scale would not do: a fault that carries no shear
has |tau| of 1e-8 Pa next to sigmaN of 1e7 Pa, pure round-off that differs between any two
factorisations. Why 1e-9: the tables carry 10 significant digits, and the runs differ only by the
order of MUMPS's and CHOLMOD's eliminations, i.e. round-off amplified by the condition number
(measured: at most 4.3e-14 on the P2 paper benchmark, 3e-11 on cases/strikeSlipFault and
2.8e-10 on cases/fractureNetwork, whose sigmaN of 1e7-1e8 Pa is mostly the in-situ stress added
to a solved perturbation); a wrong rank's share of the
matrix or a solution not shared by all ranks changes the slip in the first digits.
Prints the largest difference per case; exits 1 on any mismatch or if there is nothing to compare.
--tolerance T replaces 1e-9 for a run whose factor is approximate by design (a low-rank MUMPS
factor, tests/regression/mumpsMemory.sh, which says why its T).
"""
import glob
import math
import os
import sys


def read_table(path):
    header, status, rows, marks = None, None, [], []
    with open(path) as f:
        for line in f:
            if line.startswith("# status"):
                status = line.split()[2]
            elif line.startswith("# junction") or line.startswith("# intersection"):
                marks.append(line)
            elif line.startswith("#") and header is None:
                header = line[1:].split()
            elif line.startswith("#") or not line.strip():
                continue
            else:
                rows.append(line.split())
    return header, status, rows, marks


def number(text):
    return float(text)  # 'nan' reads as NaN


def main():
    args = sys.argv[1:]
    tolerance = 1e-9
    if len(args) >= 2 and args[0] == "--tolerance":
        tolerance = float(args[1])
        args = args[2:]
    if len(args) < 2:
        print(__doc__)
        return 2
    reference, runs = args[0], args[1:]
    tables = sorted(glob.glob(os.path.join(reference, "*", "fractures", "*.dat")))
    if not tables:
        print(f"no fracture tables under {reference}")
        return 1
    failures = 0
    for run in runs:
        worst, worst_where = 0.0, ""
        compared = 0
        for ref_path in tables:
            rel = os.path.relpath(ref_path, reference)
            path = os.path.join(run, rel)
            if not os.path.exists(path):
                print(f"{run}: missing {rel}")
                failures += 1
                continue
            h0, s0, r0, m0 = read_table(ref_path)
            h1, s1, r1, m1 = read_table(path)
            if m0 != m1:
                print(f"{run}: {rel}: the junction or intersection lines differ")
                failures += 1
            if h0 != h1 or s0 != s1 or len(r0) != len(r1) or not r0:
                print(f"{run}: {rel}: header, status ({s0} / {s1}) or row count "
                      f"({len(r0)} / {len(r1)}) differ, or no rows")
                failures += 1
                continue
            def group(name):
                if name in ("sigmaN", "residual", "sigmaNEffective", "pressure", "deltaCFS") or name.startswith("tau"):
                    return "traction"
                if name.startswith("slip") or name == "opening":
                    return "slip"
                return name

            scales = {}
            for c, name in enumerate(h0):
                if name == "state":
                    continue
                g = group(name)
                for r in r0:
                    x = number(r[c])
                    if not math.isnan(x):
                        scales[g] = max(scales.get(g, 0.0), abs(x))
            scales["ST"] = max(scales.get("ST", 0.0), 1.0)
            for c, name in enumerate(h0):
                if name == "state":
                    if [r[c] for r in r0] != [r[c] for r in r1]:
                        print(f"{run}: {rel}: the states differ")
                        failures += 1
                    continue
                a = [number(r[c]) for r in r0]
                b = [number(r[c]) for r in r1]
                scale = scales.get(group(name), 0.0)
                for x, y in zip(a, b):
                    if math.isnan(x) or math.isnan(y):
                        if math.isnan(x) != math.isnan(y):
                            print(f"{run}: {rel}: column {name}: NaN in one run only")
                            failures += 1
                        continue
                    d = abs(x - y) / scale if scale > 0 else abs(x - y)
                    compared += 1
                    if d > worst:
                        worst, worst_where = d, f"{rel} column {name}"
                    if d > tolerance and abs(x - y) > 1e-300:
                        print(f"{run}: {rel}: column {name}: {x} against {y} "
                              f"(difference {d:.3g} of the column's scale)")
                        failures += 1
                        break
        print(f"{run}: {compared} values in {len(tables)} tables, largest difference "
              f"{worst:.3g} of its column's scale ({worst_where})")
        if compared == 0:
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
