#!/bin/bash
# The handouts' size: for every problem given and every method, the LaTeX handout's pages
# (pdflatex twice), its overfull boxes and the widest of them, and the Markdown handout's
# text less its <svg> pictures, one line each:
# `name bodies method pages overfull widest-pt markdown-bytes`; then the same for the student
# worksheet (`method+student`, no Markdown size). Problems of one or two bodies over 4 pages
# are marked `OVER`.
#
#   tools/bench/pages.sh target/release/mbd-tutor problems/*.json
#
# PAGES_KEEP=DIR keeps every .tex, .log and .pdf there (to look at the pages:
# `pdftoppm -png -r 60 DIR/NAME-METHOD.pdf DIR/NAME-METHOD`). PAGES_METHODS overrides the
# methods (default: newton-euler motion-law kane lagrange); PAGES_STUDENT=0 leaves out the
# worksheets; PAGES_JOBS runs that many problems at once (default 2); PAGES_TEMPLATES=DIR
# sets the handouts with the templates of DIR (`explain --templates`); PAGES_PASSES=1 runs
# pdflatex once (the page count is the same: the tables' widths are fixed).
set -euo pipefail
bin=$(realpath "$1"); shift
if [ -n "${PAGES_KEEP:-}" ]; then
  mkdir -p "$PAGES_KEEP"; work=$(realpath "$PAGES_KEEP")
else
  work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fi
methods=${PAGES_METHODS:-newton-euler motion-law kane lagrange}
student=${PAGES_STUDENT:-1}
[ -n "${PAGES_TEMPLATES:-}" ] && PAGES_TEMPLATES=$(realpath "$PAGES_TEMPLATES")

# One handout: NAME BODIES METHOD FILE [--student].
one() {
  local name=$1 bodies=$2 method=$3 path=$4 flag=${5:-}
  local tag=$method; [ -n "$flag" ] && tag="$method+student"
  local tex="$work/$name-$tag.tex"
  local templates=(); [ -n "${PAGES_TEMPLATES:-}" ] && templates=(--templates "$PAGES_TEMPLATES")
  if ! "$bin" explain "$path" --method "$method" --format latex $flag "${templates[@]}" -o "$tex" 2>/dev/null; then
    echo "$name $bodies $tag - - - -"; return
  fi
  (cd "$work" && for _ in $(seq "${PAGES_PASSES:-2}"); do
     pdflatex -interaction=nonstopmode "$tex" >/dev/null 2>&1 || true; done)
  local log="${tex%.tex}.log"
  local pages; pages=$(pdfinfo "${tex%.tex}.pdf" 2>/dev/null | awk '/^Pages/ {print $2}')
  local overfull; overfull=$(grep -c 'Overfull \\hbox' "$log" || true)
  local widest; widest=$(grep -o 'Overfull \\hbox ([0-9.]*pt' "$log" | grep -o '[0-9.]*' \
    | sort -g | tail -1 || true)
  local text=-
  if [ -z "$flag" ]; then
    text=$("$bin" explain "$path" --method "$method" --format markdown \
      | python3 -c 'import re, sys; print(len(re.sub(r"<svg.*?</svg>", "", sys.stdin.read(), flags=re.S).encode()))')
  fi
  local mark=""; [ "$bodies" -le 2 ] && [ "${pages:-0}" -gt 4 ] && mark=" OVER"
  echo "$name $bodies $tag ${pages:--} $overfull ${widest:-0} $text$mark"
}

problem() {
  local path; path=$(realpath "$1")
  local name; name=$(basename "$1" .json)
  local bodies; bodies=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1])).get("bodies", {})))' "$path")
  for method in $methods; do
    one "$name" "$bodies" "$method" "$path"
    [ "$student" = 1 ] && one "$name" "$bodies" "$method" "$path" --student
  done
}
export -f one problem
export bin work methods student PAGES_TEMPLATES

printf '%s\n' "$@" | xargs -P "${PAGES_JOBS:-2}" -I{} bash -c 'problem "$1"' _ {}
