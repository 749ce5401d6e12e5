#!/bin/sh
# README's sections written by radview itself: the lines between
#   <!-- begin: radview ARGS -->   and   <!-- end: radview ARGS -->
# are what `radview ARGS` prints.
#   readme_section.sh README RADVIEW ARGS...            checks it (exit 1 naming the difference)
#   readme_section.sh --update README RADVIEW ARGS...   writes it
set -eu
update=false
if [ "$1" = --update ]; then update=true; shift; fi
readme=$1 radview=$2
shift 2
begin="<!-- begin: radview $* -->"
end="<!-- end: radview $* -->"
grep -qxF "$begin" "$readme" && grep -qxF "$end" "$readme" || {
  echo "$readme: no section '$begin' ... '$end'" >&2
  exit 1
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$radview" "$@" > "$tmp/now"
awk -v b="$begin" -v e="$end" '$0 == e { inside = 0 } inside { print } $0 == b { inside = 1 }' "$readme" > "$tmp/readme"
if $update; then
  awk -v b="$begin" -v e="$end" -v now="$tmp/now" '
    $0 == e { while ((getline line < now) > 0) print line; inside = 0 }
    !inside { print }
    $0 == b { inside = 1 }' "$readme" > "$tmp/new"
  cat "$tmp/new" > "$readme"
elif ! diff -u "$tmp/readme" "$tmp/now"; then
  echo "$readme: the section '$begin' is not what 'radview $*' prints now;" \
       "rewrite it with: tests/docs/readme_section.sh --update $readme $radview $*" >&2
  exit 1
fi
