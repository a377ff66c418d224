// Headless Chromium reads the handouts and pictures as a student sees them. Run by
// tests/handouts_in_browser.rs and tests/draw/browser.rs:  node handouts.js MODE ARGS...; exits 0 when every check passes
// and prints what failed otherwise.
//   texts FILE...             no text node of any page (HTML or SVG) shows a literal ^, _ or ˆ
//   overdots HTML...          every dot over a letter is inked, above its letter, clear of its
//                             ink and unclipped,
//                             and q, q̇, q̈ differ where they stand in fractions and brackets
//   hats HTML...              every hat over a unit vector's letter stands over its middle,
//                             above it
//   friction EXPECTED FILE... the arrow labelled one of EXPECTED.labels (or EXPECTED.label) points along EXPECTED.page
//                             (a unit vector on the page, y downward) in every picture of FILE
//   arrows FILE...            no two force arrows of a picture lie on top of each other: their
//                             heads apart, and two along one line of different lengths
//   triads SVG...             each frame's unit vectors (g.triad) clear of every body's
//                             outline and every pin
//   labels SVG...             no label of a picture overlaps another
//   shapes EXPECTED SVG...    each body of EXPECTED.bodies drawn in a picture is its shape
//                             (data-shape), not a point: a rod as long as the bar, a block
//                             of some size, a bar (elongated) longer than thick
//   results HTML...           no check: prints, a line a page, {"file": HTML, "result": R},
//                             R the JSON the page's own script wrote into <pre id="result">
//                             (tests/draw/measure.js); two pages at a time, one browser
'use strict';
const { chromium } = require('playwright-core');

const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const failures = [];
function check(ok, what) {
  if (!ok) failures.push(what);
  if (!ok || process.env.VERBOSE) console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
}

async function browser() {
  return chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
}

// Opens each file in turn in one page at 100 % zoom and calls `visit(page, file)`.
async function each(files, visit) {
  const b = await browser();
  const page = await b.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  for (const file of files) {
    await page.goto('file://' + file);
    await visit(page, file);
  }
  await b.close();
}

// Every text node outside scripts and styles, with the characters a reader must not see.
async function texts(files) {
  await each(files, async (page, file) => {
    const bad = await page.evaluate(() => {
      const found = [];
      const walker = document.createTreeWalker(document.documentElement, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n; n = walker.nextNode()) {
        const parent = n.parentNode ? n.parentNode.nodeName.toLowerCase() : '';
        if (parent === 'script' || parent === 'style') continue;
        // The hat an accent's <mo> sets over its letter in a <mover> is drawn, not literal.
        const accent = parent === 'mo' && n.parentNode.parentNode && n.parentNode.parentNode.nodeName.toLowerCase() === 'mover'
          && n.parentNode === n.parentNode.parentNode.lastElementChild && n.nodeValue.trim() === 'ˆ';
        if (accent) continue;
        if (/[\^_ˆ]/.test(n.nodeValue)) found.push(`<${parent}> ${n.nodeValue.trim().slice(0, 80)}`);
      }
      return found;
    });
    check(bad.length === 0, `${file}: no literal ^, _ or ˆ in its text (${bad.length} found) ${bad.slice(0, 5).join(' | ')}`);
  });
}

// The overdots of a page: for each <mover> whose accent is a dot, the boxes of the dot and
// its letter, whether an ancestor that clips (overflow not visible) cuts the dot, where it
// stands (in a fraction, in brackets), and a key naming the letter and its dots.
function measureDots() {
  const DOTS = { '˙': 1, '¨': 2, '\u0307': 1, '\u0308': 2, '\u20db': 3 };
  const found = [];
  for (const mover of document.querySelectorAll('mover')) {
    const [base, accent] = mover.children;
    if (!base || !accent) continue;
    const dots = DOTS[accent.textContent.trim()];
    if (!dots) continue;
    const a = accent.getBoundingClientRect();
    const q = base.getBoundingClientRect();
    let clipped = false;
    for (let e = mover.parentElement; e; e = e.parentElement) {
      const style = getComputedStyle(e);
      if (style.overflowX === 'visible' && style.overflowY === 'visible') continue;
      const c = e.getBoundingClientRect();
      if (a.top < c.top - 0.5 || a.bottom > c.bottom + 0.5 || a.left < c.left - 0.5 || a.right > c.right + 0.5) clipped = true;
    }
    const inFraction = mover.closest('mfrac') !== null;
    let bracketed = false;
    for (let e = mover.parentElement; e && !bracketed; e = e.parentElement) {
      for (const mo of e.children) {
        if (mo.nodeName.toLowerCase() === 'mo' && /[([{]/.test(mo.textContent)) bracketed = true;
      }
      if (e.nodeName.toLowerCase() === 'math') break;
    }
    found.push({ letter: base.textContent.trim(), dots, inFraction, bracketed, clipped,
      dot: [a.left, a.top, a.width, a.height], base: [q.left, q.top, q.width, q.height] });
  }
  return found;
}

// The pixels of a full-page screenshot (`shot`, base64 PNG) in each box (x, y, w, h in the
// page), read back through a canvas in the page: per box, its rows of 1 where the pixel is
// darker than `level` (of 255, averaged over the channels) and 0 elsewhere.
async function darkPixels(page, shot, boxes, level) {
  return page.evaluate(async ([data, boxes, level]) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + data;
    await img.decode();
    const canvas = document.createElement('canvas');
    canvas.width = img.width; canvas.height = img.height;
    const ctx = canvas.getContext('2d');
    ctx.drawImage(img, 0, 0);
    return boxes.map(([x, y, w, h]) => {
      const [x0, y0] = [Math.max(0, Math.floor(x)), Math.max(0, Math.floor(y))];
      const [cw, ch] = [Math.max(1, Math.ceil(w)), Math.max(1, Math.ceil(h))];
      const px = ctx.getImageData(x0, y0, cw, ch).data;
      const rows = [];
      for (let r = 0; r < ch; r += 1) {
        const row = [];
        for (let c = 0; c < cw; c += 1) {
          const k = 4 * (r * cw + c);
          row.push(px[k] + px[k + 1] + px[k + 2] < 3 * level ? 1 : 0);
        }
        rows.push(row);
      }
      return rows;
    });
  }, [shot, boxes, level]);
}

async function fullShot(page) {
  return (await page.screenshot({ fullPage: true })).toString('base64');
}

// The number of dark pixels in each box of `boxes` (x, y, w, h in the page), a pixel's
// margin around it included.
async function ink(page, boxes) {
  const around = boxes.map(([x, y, w, h]) => [x - 1, y - 1, w + 2, h + 2]);
  const masks = await darkPixels(page, await fullShot(page), around, 160);
  return masks.map((rows) => rows.reduce((sum, row) => sum + row.reduce((a, b) => a + b, 0), 0));
}

// For each dotted letter, the white rows between the lowest ink of its dots and the highest
// ink of its letter, in the column the dots stand over: three screenshots of the page, with
// the dots hidden, the letters hidden and both hidden, so what else is drawn there (a
// fraction's bar, a neighbour) is not counted. `null` where either has no ink there.
async function clearances(page, found) {
  // Across, only where the dots stand over the letter: a neighbour's accent may reach into
  // the dots' own box.
  const boxes = found.map((d) => {
    const [x, y, w, h] = d.dot;
    const [bx, by, bw, bh] = d.base;
    const [left, right] = [Math.max(x, bx), Math.min(x + w, bx + bw)];
    const top = Math.min(y, by);
    return [left, top, Math.max(1, right - left), Math.max(y + h, by + bh) - top];
  });
  // One screenshot of the whole page, cut into the boxes in the page itself.
  const masks = async (css) => {
    const style = await page.addStyleTag({ content: css });
    const shot = await fullShot(page);
    await style.evaluate((e) => e.remove());
    return darkPixels(page, shot, boxes, 200);
  };
  const hideDots = 'mover > :nth-child(2) { visibility: hidden !important; }';
  const hideLetters = 'mover > :first-child { visibility: hidden !important; }';
  const [letters, marks, neither] = [await masks(hideDots), await masks(hideLetters), await masks(hideDots + hideLetters)];
  return boxes.map((_, k) => {
    const own = (m) => m[k].map((row, r) => row.some((v, c) => v && !neither[k][r][c]));
    const letterRows = own(letters);
    const dotRows = own(marks);
    const letterTop = letterRows.indexOf(true);
    const dotBottom = dotRows.lastIndexOf(true);
    if (letterTop < 0 || dotBottom < 0) return null;
    return letterTop - dotBottom - 1;
  });
}

async function overdots(files) {
  await each(files, async (page, file) => {
    const dots = await page.evaluate(measureDots);
    check(dots.length > 0, `${file}: has dotted letters`);
    const hard = dots.filter((d) => d.inFraction || d.bracketed);
    check(hard.length > 0, `${file}: has dotted letters in fractions or brackets`);
    let faults = 0;
    for (const d of dots) {
      const [x, y, w, h] = d.dot;
      const where = `${d.letter}${'\u0307'.repeat(d.dots)}${d.inFraction ? ' in a fraction' : ''}${d.bracketed ? ' in brackets' : ''}`;
      const fine = w >= 1 && h >= 1 && !d.clipped && y + h / 2 <= d.base[1] + 0.25 * d.base[3];
      if (!fine) {
        faults += 1;
        if (faults <= 5) check(false, `${file}: the dot of ${where} at ${d.dot.map((v) => v.toFixed(1))} over ${d.base.map((v) => v.toFixed(1))}${d.clipped ? ' is clipped' : ''}`);
      }
    }
    check(faults === 0, `${file}: ${dots.length} dots drawn above their letters, none clipped (${faults} not)`);
    // The dots seen: the box above each letter has ink, and two dots more ink than one.
    const sample = [];
    for (const n of [1, 2]) {
      const some = hard.filter((d) => d.dots === n).slice(0, 6);
      sample.push(...some);
    }
    const shares = await ink(page, sample.map((d) => d.dot));
    sample.forEach((d, k) => check(shares[k] >= d.dots, `${file}: the dot of ${d.letter} (${d.dots}) has ink: ${shares[k]} dark pixels`));
    const mean = (n) => {
      const s = sample.map((d, k) => [d, shares[k]]).filter(([d]) => d.dots === n).map(([, v]) => v);
      return s.length ? s.reduce((x, y) => x + y, 0) / s.length : null;
    };
    const [one, two] = [mean(1), mean(2)];
    if (one !== null && two !== null) check(two > one, `${file}: two dots have more ink than one (${two} > ${one})`);
    // The dots clear of their letter: a row of white between the dots' ink and the letter's.
    const near = dots.filter((d) => !d.clipped);
    const gaps = await clearances(page, near);
    let touching = 0;
    near.forEach((d, k) => {
      if (gaps[k] !== null && gaps[k] < 1) {
        touching += 1;
        if (touching <= 5) check(false, `${file}: the dots of ${d.letter} touch it (${gaps[k]} px apart)`);
      }
    });
    check(touching === 0, `${file}: ${near.length} dotted letters, their dots clear of the letter (${touching} not)`);
  });
}

// The hats of a page: for each <mover> whose accent is a hat, the boxes of the hat and its
// letter and the letter itself.
function measureHats() {
  const HATS = ['ˆ', '\u0302', '^'];
  const found = [];
  for (const mover of document.querySelectorAll('mover')) {
    const [base, accent] = mover.children;
    if (!base || !accent || !HATS.includes(accent.textContent.trim())) continue;
    const a = accent.getBoundingClientRect();
    const q = base.getBoundingClientRect();
    if (a.width === 0 && q.width === 0) continue;
    found.push({ letter: base.textContent.trim(), hat: [a.left, a.top, a.width, a.height], base: [q.left, q.top, q.width, q.height] });
  }
  return found;
}

// Every hat stands over its letter: across, the middle of the hat's ink within a quarter of
// the letter's inked width (and a pixel) of the middle of the letter's ink, and the hat's
// ink above the letter's. Three screenshots, the hats hidden, the letters hidden, both,
// so that what else is drawn there is not counted.
async function hats(files) {
  await each(files, async (page, file) => {
    const found = await page.evaluate(measureHats);
    check(found.length > 0, `${file}: has unit vectors with hats`);
    const boxes = found.map((d) => {
      const [x, y, w, h] = d.hat;
      const [bx, by, bw, bh] = d.base;
      const left = Math.min(x, bx) - 4;
      const top = Math.min(y, by) - 2;
      return [left, top, Math.max(x + w, bx + bw) + 4 - left, Math.max(y + h, by + bh) + 2 - top];
    });
    const masks = async (css) => {
      const style = await page.addStyleTag({ content: css });
      const shot = await fullShot(page);
      await style.evaluate((e) => e.remove());
      return darkPixels(page, shot, boxes, 200);
    };
    const hideHats = 'mover > :nth-child(2) { visibility: hidden !important; }';
    const hideLetters = 'mover > :first-child { visibility: hidden !important; }';
    const [letters, marks, neither] = [await masks(hideHats), await masks(hideLetters), await masks(hideHats + hideLetters)];
    let faults = 0;
    let measured = 0;
    found.forEach((d, k) => {
      const own = (m) => m[k].map((row, r) => row.map((v, c) => v && !neither[k][r][c]));
      const extent = (m) => {
        let [left, right, top, bottom, sum, n] = [Infinity, -Infinity, Infinity, -Infinity, 0, 0];
        m.forEach((row, r) => row.forEach((v, c) => {
          if (!v) return;
          left = Math.min(left, c); right = Math.max(right, c);
          top = Math.min(top, r); bottom = Math.max(bottom, r);
          sum += c; n += 1;
        }));
        return n ? { left, right, top, bottom, middle: (left + right) / 2 } : null;
      };
      const [letter, hat] = [extent(own(letters)), extent(own(marks))];
      if (!letter || !hat) return;
      measured += 1;
      const off = Math.abs(hat.middle - letter.middle);
      const width = letter.right - letter.left + 1;
      const fine = off <= 0.25 * width + 1 && hat.bottom < letter.bottom;
      if (!fine) {
        faults += 1;
        if (faults <= 5) check(false, `${file}: the hat of ${d.letter} stands ${off.toFixed(1)} px off its middle (letter ${width} px wide, hat rows ${hat.top}-${hat.bottom}, letter ${letter.top}-${letter.bottom})`);
      }
    });
    check(measured > 0, `${file}: hats measured against their letters`);
    check(faults === 0, `${file}: ${measured} hats over the middle of their letters (${faults} not)`);
  });
}

// Every straight force arrow of the page: its label, its tail and head on the page (through
// the element's screen transform), the box of its head and its picture.
function measureArrows() {
  const out = [];
  const pictures = [...document.querySelectorAll('svg')];
  pictures.forEach((svg, k) => {
    for (const g of svg.querySelectorAll('g.force')) {
      const line = g.querySelector('line');
      const path = g.querySelector('path:last-of-type');
      const box = (e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
      const item = { picture: k, title: (svg.querySelector('title') || {}).textContent || '', label: g.getAttribute('data-label'), kind: g.getAttribute('data-kind'), head: path ? box(path) : null, box: box(g) };
      if (line) {
        const m = line.getScreenCTM();
        const at = (x, y) => { const p = new DOMPoint(x, y).matrixTransform(m); return [p.x, p.y]; };
        item.tail = at(line.x1.baseVal.value, line.y1.baseVal.value);
        item.tip = at(line.x2.baseVal.value, line.y2.baseVal.value);
      }
      out.push(item);
    }
  });
  return out;
}

async function friction(expectedPath, files) {
  const expected = JSON.parse(require('fs').readFileSync(expectedPath, 'utf8'));
  await each(files, async (page, file) => {
    const wanted = expected.labels || [expected.label];
    const arrows = (await page.evaluate(measureArrows)).filter((a) => wanted.includes(a.label));
    check(arrows.length > 0, `${file}: an arrow labelled ${wanted.join(' or ')}`);
    for (const a of arrows) {
      const d = [a.tip[0] - a.tail[0], a.tip[1] - a.tail[1]];
      const n = Math.hypot(d[0], d[1]);
      const along = (d[0] * expected.page[0] + d[1] * expected.page[1]) / n;
      const headCentre = [(a.head[0] + a.head[2]) / 2, (a.head[1] + a.head[3]) / 2];
      const headAtTip = Math.hypot(headCentre[0] - a.tip[0], headCentre[1] - a.tip[1]) < Math.hypot(headCentre[0] - a.tail[0], headCentre[1] - a.tail[1]);
      check(along > 0.999 && headAtTip, `${file} (${a.title}): ${a.label} drawn along ${d.map((v) => (v / n).toFixed(3))} with its head at the tip, against the slip (${expected.page})`);
    }
  });
}

// Whether two straight arrows share their line over more than a few pixels in one sense.
function alongEachOther(a, b) {
  if (!a.tail || !b.tail) return false;
  const u = [a.tip[0] - a.tail[0], a.tip[1] - a.tail[1]];
  const v = [b.tip[0] - b.tail[0], b.tip[1] - b.tail[1]];
  const lu = Math.hypot(u[0], u[1]); const lv = Math.hypot(v[0], v[1]);
  if (lu < 1 || lv < 1) return false;
  const cos = (u[0] * v[0] + u[1] * v[1]) / (lu * lv);
  if (cos < 0.995) return false;
  const w = [b.tail[0] - a.tail[0], b.tail[1] - a.tail[1]];
  const off = Math.abs(u[0] * w[1] - u[1] * w[0]) / lu;
  if (off > 3) return false;
  const s0 = (w[0] * u[0] + w[1] * u[1]) / lu;
  const s1 = s0 + lv * cos;
  return Math.min(lu, Math.max(s0, s1)) - Math.max(0, Math.min(s0, s1)) > 3;
}

function boxesMeet(p, q) {
  return p && q && p[0] < q[2] - 0.5 && q[0] < p[2] - 0.5 && p[1] < q[3] - 0.5 && q[1] < p[3] - 0.5;
}

async function arrows(files) {
  let total = 0;
  await each(files, async (page, file) => {
    const all = await page.evaluate(measureArrows);
    total += all.length;
    for (let i = 0; i < all.length; i += 1) {
      for (let j = i + 1; j < all.length; j += 1) {
        const [a, b] = [all[i], all[j]];
        if (a.picture !== b.picture) continue;
        const heads = boxesMeet(a.head, b.head);
        // A longer arrow may share its line with a shorter one (the pictures' caption says
        // so): on top of each other only when their tips meet too.
        const along = alongEachOther(a, b) && Math.hypot(a.tip[0] - b.tip[0], a.tip[1] - b.tip[1]) < 8;
        check(!heads && !along, `${file} (${a.title}): ${a.label} and ${b.label} ${heads ? 'heads meet' : along ? 'lie along each other' : 'apart'}`);
      }
    }
  });
  // A torque-free body has none; the pictures as a whole have many.
  check(total > files.length, `${files.length} pictures hold ${total} force arrows`);
}

// Each triad's box (its arrows and heads, in the picture's units) against the bodies'
// outlines (a grid of points in the box tried on every body's strokes: a large disc may
// hold its unit vectors inside) and the pins (the joints' circles).
function measureTriads() {
  const out = [];
  for (const svg of document.querySelectorAll('svg')) {
    const title = (svg.querySelector('title') || {}).textContent || '';
    const shapes = [...svg.querySelectorAll('g.body path, g.body circle, g.body ellipse, g.body polygon')];
    const pins = [...svg.querySelectorAll('circle.joint')];
    svg.querySelectorAll('g.triad').forEach((g, k) => {
      const b = g.getBBox();
      const hits = [];
      const point = svg.createSVGPoint();
      for (let i = 0; i <= 12; i += 1) {
        for (let j = 0; j <= 12; j += 1) {
          point.x = b.x + (b.width * i) / 12;
          point.y = b.y + (b.height * j) / 12;
          for (const s of shapes) {
            // Into the shape's own units (a disc seen obliquely is a turned ellipse).
            const local = point.matrixTransform(s.getScreenCTM().inverse().multiply(svg.getScreenCTM()));
            if (s.isPointInStroke(local)) {
              hits.push(`${s.parentNode.id} at ${point.x.toFixed(1)},${point.y.toFixed(1)}`);
            }
          }
        }
      }
      for (const c of pins) {
        const [cx, cy, r] = ['cx', 'cy', 'r'].map((a) => Number(c.getAttribute(a)));
        const nx = Math.max(b.x, Math.min(cx, b.x + b.width));
        const ny = Math.max(b.y, Math.min(cy, b.y + b.height));
        if (Math.hypot(nx - cx, ny - cy) < r + 1) hits.push(c.id);
      }
      out.push({ title, k, hits: [...new Set(hits)].slice(0, 4) });
    });
  }
  return out;
}

async function triads(files) {
  let total = 0;
  await each(files, async (page, file) => {
    for (const t of await page.evaluate(measureTriads)) {
      total += 1;
      check(t.hits.length === 0, `${file} (${t.title}): unit vectors ${t.k} clear of bodies and pins (${t.hits.join(', ')})`);
    }
  });
  check(total > 0, `${files.length} pictures hold ${total} triads`);
}

// Every label of a picture (its <text> but the title, where drawn) against every other.
async function labels(files) {
  await each(files, async (page, file) => {
    const found = await page.evaluate(() => {
      const out = [];
      for (const svg of document.querySelectorAll('svg')) {
        const title = (svg.querySelector('title') || {}).textContent || '';
        // The picture's title is drawn over it where no heading names it already.
        const texts = [...svg.querySelectorAll('g.labels text')];
        const bare = (s) => s.replace(/\s+/g, '');
        const titled = texts.length > 0 && bare(texts[0].textContent) === bare(title);
        const boxes = texts.slice(titled ? 1 : 0).map((t) => {
          const r = t.getBoundingClientRect();
          return { text: t.textContent, box: [r.left, r.top, r.right, r.bottom] };
        });
        for (let i = 0; i < boxes.length; i += 1) {
          for (let j = i + 1; j < boxes.length; j += 1) {
            const [p, q] = [boxes[i].box, boxes[j].box];
            // Glyph boxes hold the line's leading: 2 pixels of it may touch.
            if (p[0] < q[2] - 2 && q[0] < p[2] - 2 && p[1] < q[3] - 2 && q[1] < p[3] - 2) {
              out.push(`${title}: ${boxes[i].text} on ${boxes[j].text}`);
            }
          }
        }
      }
      return out;
    });
    check(found.length === 0, `${file}: no two labels overlap (${found.join(' | ')})`);
  });
}

// Each body group of a picture, as laid out: its id, data-shape, box (the picture's units)
// and the picture's scale (its units per metre, from data-projection's first row).
function measureBodies() {
  const out = [];
  for (const svg of document.querySelectorAll('svg')) {
    const n = (svg.getAttribute('data-projection') || '').split(/\s+/).map(Number);
    const scale = Math.hypot(n[0] || 0, n[1] || 0, n[2] || 0);
    for (const g of svg.querySelectorAll('g.body')) {
      const b = g.getBBox();
      out.push({ id: g.id, shape: g.getAttribute('data-shape'), box: [b.width, b.height], scale });
    }
  }
  return out;
}

async function shapes(expectedPath, files) {
  const expected = JSON.parse(require('fs').readFileSync(expectedPath, 'utf8')).bodies;
  const seen = {};
  await each(files, async (page, file) => {
    for (const body of await page.evaluate(measureBodies)) {
      const want = expected[body.id.replace(/^body-/, '')];
      if (!want) continue;
      seen[body.id] = (seen[body.id] || 0) + 1;
      const [w, h] = body.box;
      // A rod's box is its diagonal's; a block's its sides.
      const long = Math.hypot(w, h); const thick = Math.min(w, h);
      let fine = body.shape === want.shape && long >= 12 && (!want.thick || thick >= want.thick);
      let what = `${body.shape} of ${w.toFixed(1)} by ${h.toFixed(1)}`;
      if (want.length) {
        // A bar drawn from pin to pin: as long as the bar at the picture's scale, give or
        // take the stroke's round caps.
        const bar = want.length * body.scale;
        fine = fine && long >= 0.95 * bar && long <= bar + 16;
        what += `, the bar ${bar.toFixed(1)} long`;
      }
      if (want.elongated) {
        fine = fine && w >= want.elongated * h;
        what += `, ${want.elongated} times as long as thick`;
      }
      check(fine, `${file}: ${body.id} drawn as a ${want.shape} (${what})`);
    }
  });
  for (const name of Object.keys(expected)) {
    check(seen[`body-${name}`] > 0, `body ${name} drawn in ${seen[`body-${name}`] || 0} of the pictures`);
  }
}

// What each page's script wrote into <pre id="result">, printed a line a page; two pages
// of one browser at a time, each taking every other file.
async function results(files) {
  const b = await browser();
  const halves = [0, 1].map((k) => files.filter((_, i) => i % 2 === k));
  await Promise.all(halves.map(async (half) => {
    const page = await b.newPage({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
    for (const file of half) {
      await page.goto('file://' + file);
      const text = await page.textContent('#result');
      console.log(JSON.stringify({ file, result: JSON.parse(text) }));
    }
  }));
  await b.close();
}

(async () => {
  const [mode, ...args] = process.argv.slice(2);
  const modes = { texts, overdots, hats, friction: (a) => friction(a[0], a.slice(1)), arrows, triads, labels, shapes: (a) => shapes(a[0], a.slice(1)), results };
  if (!modes[mode]) { console.log(`unknown mode ${mode}`); process.exit(2); }
  try {
    await modes[mode](args);
  } catch (e) {
    check(false, `${mode}: ${e.stack || e}`);
  }
  if (failures.length) {
    console.log(`${failures.length} failed`);
    process.exit(1);
  }
  console.log('all passed');
})();
