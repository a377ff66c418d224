#!/bin/bash
# The handouts' size: for every problem given and every method, the LaTeX handout's pages
# (pdflatex twice), its overfull boxes, and the Markdown handout's text less its <svg>
# pictures, one line each: `name method pages overfull markdown-bytes`.
#
#   tools/bench/pages.sh target/release/mbd-tutor problems/*.json problems/validation/*.json
set -euo pipefail
bin=$(realpath "$1"); shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for file in "$@"; do
  path=$(realpath "$file")
  for method in newton-euler motion-law kane; do
    name=$(basename "$file" .json)
    tex="$work/$name-$method.tex"
    "$bin" explain "$path" --method "$method" --format latex -o "$tex"
    (cd "$work" && pdflatex -interaction=nonstopmode "$tex" >/dev/null 2>&1 || true
     pdflatex -interaction=nonstopmode "$tex" >/dev/null 2>&1 || true)
    log="${tex%.tex}.log"
    pages=$(pdfinfo "${tex%.tex}.pdf" | awk '/^Pages/ {print $2}')
    overfull=$(grep -c Overfull "$log" || true)
    text=$("$bin" explain "$path" --method "$method" --format markdown \
      | python3 -c 'import re, sys; print(len(re.sub(r"<svg.*?</svg>", "", sys.stdin.read(), flags=re.S).encode()))')
    echo "$name $method $pages $overfull $text"
  done
done
