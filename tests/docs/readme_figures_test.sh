#!/usr/bin/env bash
# The docs' measured tables are what the benchmarks' result files give: the check passes on the
# repository, fails naming the block when a figure in README is changed by hand, and --write
# puts it back (tests/bench/readme_figures.py).
# usage: readme_figures_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source=$1 work=$2
figures="$source/tests/bench/readme_figures.py"
/usr/bin/python3 "$figures" --root "$source"

rm -rf "$work" && mkdir -p "$work/assets" "$work/tests/bench" "$work/renderer/bench"
cp "$source/README.md" "$work/"
cp "$source/renderer/bench/README.md" "$work/renderer/bench/"
cp -r "$source/assets/bench" "$work/assets/"
cp -r "$source/tests/bench/results" "$work/tests/bench/"
# One figure of fig. 9.14's table edited by hand: the first estimate before an interval.
python3 - "$work/README.md" <<'PY'
import re, sys
path = sys.argv[1]
text = open(path).read()
start = text.index("<!-- begin: figures trade-fig9_14 -->")
m = re.compile(r"\| ([\d.]+) \[").search(text, start)
text = text[:m.start(1)] + "9" + m.group(1) + text[m.end(1):]
open(path, "w").write(text)
PY
if /usr/bin/python3 "$figures" --root "$work" 2> "$work/check.err"; then
  echo "the check passed a README whose figure was edited by hand"; exit 1
fi
grep -q "differ from the result files in: trade-fig9_14 in README.md" "$work/check.err"
/usr/bin/python3 "$figures" --root "$work" --write > /dev/null
/usr/bin/python3 "$figures" --root "$work"
cmp "$work/README.md" "$source/README.md"
echo "readme_figures_test: ok"
