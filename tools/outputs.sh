#!/usr/bin/env bash
# Writes every output of every bundled problem into DIR, one file per problem x method x
# format, so that two builds can be compared byte for byte:
#   tools/outputs.sh BIN DIR          e.g. tools/outputs.sh target/release/mbd-tutor /tmp/a
#   diff -r /tmp/a /tmp/b             nothing printed: the outputs are byte-identical
# Covers explain (markdown, latex, html; worked and student; with --linearize; at rest with
# --statics by every method), draw (SVG, TikZ, motion.svg), solve, answer and linearize as
# JSON.
set -u
bin=$(realpath "$1"); out=$2
mkdir -p "$out"
cd "$(dirname "$0")/.."
for p in problems/*.json problems/validation/*.json; do
  name=$(basename "$p" .json)
  [ "${p#problems/validation/}" != "$p" ] && name="validation-$name"
  for m in motion-law newton-euler kane lagrange; do
    for f in markdown latex html; do
      "$bin" explain "$p" --method $m --format $f >"$out/$name.$m.$f" 2>&1
    done
    "$bin" explain "$p" --method $m --format markdown --student >"$out/$name.$m.student.md" 2>&1
    "$bin" solve "$p" --method $m --format json >"$out/$name.$m.solve.json" 2>&1
    mkdir -p "$out/$name.$m.draw"
    "$bin" draw "$p" --method $m --tikz -o "$out/$name.$m.draw" >/dev/null 2>&1
  done
  for m in motion-law newton-euler kane lagrange; do
    for f in markdown latex html; do
      "$bin" explain "$p" --statics --method $m --format $f >"$out/$name.$m.statics.$f" 2>&1
    done
    "$bin" explain "$p" --statics --method $m --format markdown --student \
      >"$out/$name.$m.statics.student.md" 2>&1
  done
  "$bin" explain "$p" --format latex --linearize >"$out/$name.linearize.tex" 2>&1
  "$bin" answer "$p" --format json >"$out/$name.answer.json" 2>&1
  "$bin" linearize "$p" --format json >"$out/$name.linearize.json" 2>&1
  mkdir -p "$out/$name.motion"
  "$bin" draw "$p" --animate --duration 1 -o "$out/$name.motion" >/dev/null 2>&1
done
