#!/usr/bin/env python3
"""Unpack a fuzzCase input (a seed or a crash reproducer) into a case folder, so that the real
binaries can be run on it:

    tests/fuzz/unpackCase.py INPUT DIR
    splitFractureNodes -case DIR && frictionSolver -case DIR

The format is fuzzCase.cpp's: files, each introduced by a line "==> <relative path>"; bytes
before the first header are ignored; a repeated path keeps its last content. DIR must not
exist. Paths fuzzCase would refuse (absolute, '..') are refused here too.
"""
import os
import sys


def unpack(data: bytes):
    """As fuzzCase.cpp's unpack: every line keeps its newline (a file's last line too)."""
    files, current = {}, None
    # Only "\n" ends a line (bytes.splitlines would also split at "\r").
    pieces = data.split(b"\n")
    lines = [p + b"\n" for p in pieces[:-1]] + ([pieces[-1]] if pieces[-1] else [])
    for line in lines:
        if line.startswith(b"==> "):
            current = line[4:].rstrip(b"\n").decode("latin-1")
            files[current] = b""
        elif current is not None:
            files[current] += line
    return files


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, dest = sys.argv[1:]
    with open(src, "rb") as f:
        files = unpack(f.read())
    if os.path.exists(dest):
        sys.exit(f"unpackCase: {dest} exists")
    for path, content in files.items():
        if path.startswith("/") or ".." in path.split("/"):
            sys.exit(f"unpackCase: refusing path {path!r}")
        full = os.path.join(dest, path)
        os.makedirs(os.path.dirname(full) or dest, exist_ok=True)
        with open(full, "wb") as f:
            f.write(content)
    print(f"{dest}: {len(files)} files")


if __name__ == "__main__":
    main()
