#!/usr/bin/env bash
# No file of the repository cites documents a reader of it does not have: the specification the
# project started from, or an issue of the tracker by its number. The method is docs/method.md; cite its sections
# (docs/method.md#damping, ...) or say it in plain words.
#   tests/docs/references_test.sh SOURCE_DIR
# The pattern: the specification's short name as a word, in any case (not inside "spectral",
# the C library's time struct or a type name ending in it), and "issue" or "issues" followed by a
# number (with or without "#").
# It is spelt in pieces so that this file does not match it itself. Binary files (samples, figures) are not read.
# Tracked files and untracked ones not ignored are read. Skipped (77) outside a git checkout.
set -u
src=$1
git -C "$src" rev-parse --git-dir > /dev/null 2>&1 || { echo "not a git checkout: $src"; exit 77; }
w=sp i=iss
pattern="(^|[^[:alpha:]])${w}ec([^[:alnum:]_]|\$)|${i}ues? #?[0-9]"
hits=$(git -C "$src" grep --untracked -n -I -i -E "$pattern" -- .)
if [ -n "$hits" ]; then
  echo "FAIL: files cite the specification or an issue number; cite docs/method.md or use plain words:"
  echo "$hits"
  exit 1
fi
# The pattern itself must catch what it is for (a test that cannot fail is no test).
# The probes are spelt in two pieces so that this file does not match them itself.
S=SP I=ssue
for probe in "see ${S}EC section 3" "(${S}EC §7)" "the i$I 52 asks" "I$I 3:" "i${I}s 34, 35" "i$I #12"; do
  printf '%s\n' "$probe" | grep -q -i -E "$pattern" || { echo "FAIL: the pattern misses '$probe'"; exit 1; }
done
for word in "spectral" "time${w}ec t{};" "Lattice${w^}ec" "specific" "issued"; do
  printf '%s\n' "$word" | grep -q -i -E "$pattern" && { echo "FAIL: the pattern flags '$word'"; exit 1; }
done
echo "no file cites the specification or an issue number"
