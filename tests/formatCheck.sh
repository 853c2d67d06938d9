#!/usr/bin/env bash
# Format check: every C++ file the repository tracks is formatted by the project's
# .clang-format (clang-format 14, Debian's). Lists the files that differ and the command
# that fixes them; exit 1 if any does.
# Usage: tests/formatCheck.sh SOURCE_DIR
set -euo pipefail
src=${1:?usage: formatCheck.sh SOURCE_DIR}
cd "$src"
command -v clang-format >/dev/null || { echo "clang-format not found (etc/debian-packages lists it)"; exit 1; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find libfriction applications utilities tests -name '*.[ch]pp')
((${#files[@]})) || { echo "no C++ files found under $src"; exit 1; }
bad=()
for f in "${files[@]}"; do
  clang-format --style=file --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
echo "checked ${#files[@]} files, ${#bad[@]} not formatted"
if ((${#bad[@]})); then
  printf '  %s\n' "${bad[@]}"
  echo "fix with: clang-format -i --style=file <files>   (from $src)"
  exit 1
fi
