#!/usr/bin/env bash
# The tree is kept formatted (.clang-format, Debian's clang-format 14): lists every C++ file that
# clang-format would change and fails if there is one. Fix with: clang-format -i <files>.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "clang-format is not installed (bash deploy/install-deps.sh)" >&2; exit 1; }
bad=()
while IFS= read -r f; do
  clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find core server tests -name '*.cpp' -o -name '*.hpp')
if ((${#bad[@]})); then
  printf 'not clang-formatted:\n' >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "format: every C++ file is clang-formatted"
