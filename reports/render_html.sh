#!/usr/bin/env bash
# The report as a web page: MARKDOWN (reports/index.md) rendered by Debian's cmark-gfm (GitHub's
# Markdown: tables, strikethrough, autolinks) into HTML with a minimal head (UTF-8, the first "# "
# heading as title, a readable width, tables with borders). Figures stay links relative to the page,
# so the page must sit beside the Markdown (reports/index.html). Headings get GitHub's ids
# (lower case, punctuation dropped, spaces to '-', repeats numbered -1, -2, ...), so that a link
# "#some-heading" lands where it does on GitHub. The Markdown is the project's own (build/bin/report
# writes it): its raw HTML, if any, is kept (cmark-gfm --unsafe).
# Usage: reports/render_html.sh MARKDOWN HTML
# Exit status 2 if cmark-gfm is missing (make deps installs it) or the Markdown cannot be read.
set -euo pipefail
[ $# = 2 ] || { echo "usage: $0 MARKDOWN HTML" >&2; exit 2; }
md=$1 html=$2
[ -r "$md" ] || { echo "error: cannot read '$md'" >&2; exit 2; }
command -v cmark-gfm > /dev/null || { echo "error: cmark-gfm not found (make deps, or apt-get install cmark-gfm)" >&2; exit 2; }

title=$(sed -n 's/^# \{1,\}//p' "$md" | head -n 1)
title=${title:-$(basename "$md")}
escape() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g'; }

# GitHub's heading ids, on <hN>...</hN> lines as cmark-gfm writes them (one heading a line).
heading_ids() {
  perl -CSD -Mutf8 -ne '
    if (/^<h([1-6])>(.*)<\/h\1>$/) {
      my ($level, $inner) = ($1, $2);
      (my $text = $inner) =~ s/<[^>]*>//g;
      $text =~ s/&amp;/&/g; $text =~ s/&lt;/</g; $text =~ s/&gt;/>/g; $text =~ s/&quot;/"/g;
      my $id = lc $text;
      $id =~ s/[^\p{L}\p{M}\p{N}\p{Pc}\- ]//g;
      $id =~ s/ /-/g;
      my $n = $seen{$id}++;
      $id .= "-$n" if $n;
      $_ = "<h$level id=\"$id\">$inner</h$level>\n";
    }
    print;'
}

tmp=$(mktemp "$html.XXXXXX")
trap 'rm -f "$tmp"' EXIT
{
  cat <<EOF
<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>$(printf '%s' "$title" | escape)</title>
<style>
body { max-width: 62em; margin: 2em auto; padding: 0 1em; font: 16px/1.5 sans-serif; color: #222; }
h1, h2, h3 { line-height: 1.25; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 2em; }
table { border-collapse: collapse; margin: 1em 0; display: block; overflow-x: auto; font-size: 0.9em; }
th, td { border: 1px solid #999; padding: 0.25em 0.5em; vertical-align: top; }
th { background: #eee; }
img { max-width: 100%; height: auto; }
code { background: #f3f3f3; padding: 0 0.2em; }
pre { background: #f3f3f3; padding: 0.5em; overflow-x: auto; }
</style>
</head>
<body>
EOF
  cmark-gfm --unsafe --extension table --extension strikethrough --extension autolink --to html "$md" | heading_ids
  printf '</body>\n</html>\n'
} > "$tmp"
mv "$tmp" "$html"
trap - EXIT
