#!/usr/bin/python3
"""testNames.py SOURCE_DIR: no Catch2 test name holds a ';'.

catch_discover_tests hands the names to CMake as a list, where ';' separates items: a name
with one becomes two ctest entries whose filters match no test, and Catch2 exits 0 when no
test ran, so the test is silently never run. Prints the offenders and exits 1, else 0.
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
# TEST_CASE( followed by one or more adjacent string literals (the name).
pattern = re.compile(r'TEST_CASE\s*\(\s*((?:"(?:[^"\\]|\\.)*"\s*)+)')
bad = []
count = 0
for path in sorted((root / "tests").rglob("*.cpp")):
    text = path.read_text(encoding="utf-8")
    for m in pattern.finditer(text):
        name = "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', m.group(1)))
        count += 1
        if ";" in name:
            line = text.count("\n", 0, m.start()) + 1
            bad.append(f"{path.relative_to(root)}:{line}: '{name}'")
if count == 0:
    print("no TEST_CASE found: wrong folder?")
    sys.exit(1)
for b in bad:
    print(b)
print(f"checked {count} test names, {len(bad)} with ';' (ctest would split them and run none)")
sys.exit(1 if bad else 0)
