#!/usr/bin/env bash
# The report's web page in a real browser: headless Chromium (Debian's chromium, installed here if
# missing: 48 s on the project's VM; the test is skipped with exit 77 if it or cmark-gfm cannot be
# had) opens a page with tests/report/html_check.js injected, which counts on window load the images
# that did not load, the lines of raw Markdown left in the text (outside code) and the in-page links
# to a missing heading; `chromium --dump-dom` prints the counts.
#   tests/report/html_test.sh check SOURCE_DIR WORKDIR
#     1. tests/report/fixture/index.md (two images, one missing; a table without its header line,
#        left as text; a link to a heading that exists and one to a heading that does not) rendered
#        by reports/render_html.sh: exactly 1 broken image, 1 raw line, 1 missing heading, so the
#        check can fail;
#     2. the committed reports/index.html (its figures read from SOURCE_DIR/reports): 0 of each,
#        and a screenshot of its first screen, WORKDIR/first_screen.png, kept as the test's artefact.
#   tests/report/html_test.sh current SOURCE_DIR WORKDIR
#     the committed reports/index.html is reports/index.md rendered (make report writes both).
set -u
[ $# = 3 ] || { echo "usage: $0 check|current SOURCE_DIR WORKDIR" >&2; exit 2; }
mode=$1 src=$(cd "$2" && pwd) work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" || exit 1
work=$(cd "$work" && pwd)
sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo -n"

# Installs Debian package $1 for command $2 if missing (apt-get update only if the first try fails).
need() {
  command -v "$2" > /dev/null && return 0
  { $sudo env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends "$1" ||
    { $sudo env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 update -qq &&
      $sudo env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends "$1"; }; } >> "$work/apt.log" 2>&1
  command -v "$2" > /dev/null || { echo "html test: $1 cannot be installed here (see $work/apt.log): skipped"; exit 77; }
}
need cmark-gfm cmark-gfm

if [ "$mode" = current ]; then
  "$src/reports/render_html.sh" "$src/reports/index.md" "$work/index.html" || exit 1
  cmp -s "$work/index.html" "$src/reports/index.html" && { echo "reports/index.html is reports/index.md rendered"; exit 0; }
  echo "reports/index.html is not reports/index.md rendered (differences below; make report, or"
  echo "reports/render_html.sh reports/index.md reports/index.html, writes it):"
  diff "$src/reports/index.html" "$work/index.html" | head -n 20
  exit 1
fi
[ "$mode" = check ] || { echo "usage: $0 check|current SOURCE_DIR WORKDIR" >&2; exit 2; }
need chromium chromium

# chromium with its own profile (root needs --no-sandbox); the page's load event ends the wait.
browse() {
  chromium --headless --no-sandbox --disable-gpu --user-data-dir="$work/profile" --virtual-time-budget=10000 "$@" \
    2>> "$work/chromium.log"
}
# Writes PAGE_HTML with BASE (a folder URL the page's relative links resolve against, or empty)
# and the check script injected, opens it and prints the check's <pre> text.
check_page() {
  local html=$1 base=$2 page=$3
  { if [ -n "$base" ]; then sed "s|<head>|<head><base href=\"$base\">|" "$html"; else cat "$html"; fi; } |
    sed "s|</body>|<script src=\"file://$here/html_check.js\"></script></body>|" > "$page"
  browse --dump-dom "file://$page" > "$page.dom"
  sed -n '/<pre id="html-check">/,/<\/pre>/p' "$page.dom" | sed -e 's/<[^>]*>//g' -e 's/&amp;/\&/g' -e 's/&lt;/</g' -e 's/&gt;/>/g'
}
count() { sed -n "1s/.*\\b$1=\\([0-9]*\\).*/\\1/p" <<< "$2"; }
failures=0
expect() {   # NAME WHAT GOT WANTED
  if [ "$3" = "$4" ]; then echo "ok: $1: $2 = $3"; else echo "FAIL: $1: $2 = ${3:-none} (expected $4)"; failures=$((failures + 1)); fi
}

# 1. The fixture: the check finds what is wrong with it.
mkdir -p "$work/fixture/figures"
cp "$here/fixture/index.md" "$work/fixture/"
cp "$src/reports/figures/fig01_grading.png" "$work/fixture/figures/present.png"
"$src/reports/render_html.sh" "$work/fixture/index.md" "$work/fixture/index.html" || exit 1
out=$(check_page "$work/fixture/index.html" "" "$work/fixture/checked.html")
[ -n "$out" ] || { echo "FAIL: the fixture page gave no counts (chromium: $work/chromium.log)"; exit 1; }
echo "fixture: $out" | sed '2,$s/^/  /'
expect fixture "images" "$(count images "$out")" 2
expect fixture "broken images" "$(count broken "$out")" 1
expect fixture "raw Markdown lines" "$(count raw "$out")" 1
expect fixture "links to a missing heading" "$(count dangling "$out")" 1

# 2. The committed page, its figures from the source tree.
out=$(check_page "$src/reports/index.html" "file://$src/reports/" "$work/report.html")
[ -n "$out" ] || { echo "FAIL: the report page gave no counts (chromium: $work/chromium.log)"; exit 1; }
echo "reports/index.html: $out" | sed '2,$s/^/  /'
images=$(count images "$out")
[ "${images:-0}" -gt 0 ] || { echo "FAIL: reports/index.html shows no image"; failures=$((failures + 1)); }
expect report "broken images" "$(count broken "$out")" 0
expect report "raw Markdown lines" "$(count raw "$out")" 0
expect report "links to a missing heading" "$(count dangling "$out")" 0
sed "s|<head>|<head><base href=\"file://$src/reports/\">|" "$src/reports/index.html" > "$work/screen.html"
browse --screenshot="$work/first_screen.png" --window-size=1280,1000 "file://$work/screen.html" > /dev/null
[ -s "$work/first_screen.png" ] && echo "first screen: $work/first_screen.png" ||
  { echo "FAIL: no screenshot (chromium: $work/chromium.log)"; failures=$((failures + 1)); }
[ $failures = 0 ]
