// Measures every inline picture of the page in the browser that lays it out, and writes
// the measurements as JSON into <pre id="result">: the labels' own text boxes, the labels
// that overlap, the strokes that cross a label, each body group's circles and ellipses and
// the points of its strokes, and the gravity arrows; of an animated picture, its labels
// frame by frame. The test judges them.
(function () {
  const SLACK = 1.0; // a text box's padding around its letters, in px
  const out = [];
  function toSvg(svg, el, x, y) {
    const p = svg.createSVGPoint();
    p.x = x;
    p.y = y;
    return p.matrixTransform(svg.getScreenCTM().inverse().multiply(el.getScreenCTM()));
  }
  // The points along an element's outline, in the picture's coordinates.
  function outline(svg, el) {
    if (el.tagName === 'line') {
      const a = ['x1', 'y1', 'x2', 'y2'].map((k) => el[k].baseVal.value);
      return [[toSvg(svg, el, a[0], a[1]), toSvg(svg, el, a[2], a[3])]];
    }
    // Lengths in the picture's units, also for a shape drawn in its own (a moving sheet's
    // metres): its map's largest stretch.
    const m = svg.getScreenCTM().inverse().multiply(el.getScreenCTM());
    const stretch = Math.max(Math.hypot(m.a, m.b), Math.hypot(m.c, m.d));
    const length = el.getTotalLength();
    const pieces = [];
    let run = [];
    const steps = Math.max(8, Math.ceil((length * stretch) / 1.5));
    let last = null;
    for (let k = 0; k <= steps; k++) {
      const q = el.getPointAtLength((length * k) / steps);
      const p = toSvg(svg, el, q.x, q.y);
      // A path's move to a new piece shows as a jump longer than the step.
      if (last && Math.hypot(p.x - last.x, p.y - last.y) > 3 * ((length * stretch) / steps) + 2) {
        pieces.push(run);
        run = [];
      }
      run.push(p);
      last = p;
    }
    pieces.push(run);
    return pieces;
  }
  function meets(box, a, b) {
    // Liang–Barsky clipping of segment a-b against the box.
    let t0 = 0, t1 = 1;
    const d = [b.x - a.x, b.y - a.y];
    const lo = [box[0], box[1]], hi = [box[2], box[3]], s = [a.x, a.y];
    for (let k = 0; k < 2; k++) {
      for (const [p, q] of [[-d[k], s[k] - lo[k]], [d[k], hi[k] - s[k]]]) {
        if (Math.abs(p) < 1e-12) {
          if (q < 0) return false;
        } else {
          const r = q / p;
          if (p < 0) t0 = Math.max(t0, r);
          else t1 = Math.min(t1, r);
        }
      }
    }
    return t0 <= t1;
  }
  // The labels' own text boxes, the labels that overlap and the strokes that cross a
  // label, as the picture stands now.
  function labelsOf(svg, report) {
    const labels = [];
    for (const t of svg.querySelectorAll('text')) {
      const b = t.getBBox();
      const a = toSvg(svg, t, b.x, b.y), c = toSvg(svg, t, b.x + b.width, b.y + b.height);
      const box = [a.x + SLACK, a.y + SLACK, c.x - SLACK, c.y - SLACK];
      labels.push({ text: t.textContent, box });
      report.labels.push({ text: t.textContent, box });
    }
    for (let i = 0; i < labels.length; i++) {
      for (let j = i + 1; j < labels.length; j++) {
        const [a, b] = [labels[i].box, labels[j].box];
        if (a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]) {
          report.overlaps.push([labels[i].text, labels[j].text]);
        }
      }
    }
    const shapes = svg.querySelectorAll('line, polyline, polygon, path, circle, ellipse');
    for (const el of shapes) {
      const pieces = outline(svg, el);
      for (const l of labels) {
        const hit = pieces.some((run) =>
          run.some((p, k) => k > 0 && meets(l.box, run[k - 1], p)));
        if (hit) {
          const g = el.closest('[data-label], [id], [class]');
          const owner = g ? (g.getAttribute('data-label') || g.id || g.getAttribute('class')) : '';
          report.crossings.push([l.text, el.tagName + ' of ' + owner]);
        }
      }
    }
  }
  // An animated picture: its labels at some of its key frames (at most SAMPLES, the first
  // and the last among them), each as a report of its own with its time. Each key frame
  // is set by hand from the animations' values (their clocks are left out).
  const SAMPLES = 26;
  function motion(holder, svg) {
    const animations = [...svg.querySelectorAll('animate, animateTransform')];
    const tracks = animations.map((a) => ({
      el: a.parentElement,
      transform: a.tagName === 'animateTransform',
      name: a.getAttribute('attributeName'),
      type: a.getAttribute('type'),
      values: a.getAttribute('values').split(';'),
    }));
    for (const a of animations) a.remove();
    const frames = Number(svg.dataset.frames), duration = Number(svg.dataset.duration);
    const picked = new Set();
    for (let k = 0; k < SAMPLES; k++) picked.add(Math.round((k * (frames - 1)) / (SAMPLES - 1)));
    for (const frame of [...picked].sort((a, b) => a - b)) {
      const transforms = new Map();
      for (const t of tracks) {
        const value = t.values[Math.min(frame, t.values.length - 1)];
        if (t.transform) {
          transforms.set(t.el, (transforms.get(t.el) || '') + ` ${t.type}(${value})`);
        } else {
          t.el.setAttribute(t.name, value);
        }
      }
      for (const [el, transform] of transforms) el.setAttribute('transform', transform);
      const time = frames > 1 ? (duration * frame) / (frames - 1) : 0;
      const report = { file: holder.dataset.file, time, labels: [], overlaps: [], crossings: [], bodies: [], gravity: [] };
      labelsOf(svg, report);
      out.push(report);
    }
  }
  for (const holder of document.querySelectorAll('[data-file]')) {
    const svg = holder.querySelector('svg');
    if (svg.classList.contains('motion')) {
      motion(holder, svg);
      continue;
    }
    const report = { file: holder.dataset.file, labels: [], overlaps: [], crossings: [], bodies: [], gravity: [] };
    labelsOf(svg, report);
    for (const g of svg.querySelectorAll('g.body')) {
      const body = { id: g.id, shape: g.dataset.shape, circles: [], ellipses: [], points: [] };
      for (const c of g.querySelectorAll('circle')) {
        const p = toSvg(svg, c, c.cx.baseVal.value, c.cy.baseVal.value);
        body.circles.push([p.x, p.y, c.r.baseVal.value]);
      }
      for (const e of g.querySelectorAll('ellipse')) {
        const p = toSvg(svg, e, e.cx.baseVal.value, e.cy.baseVal.value);
        body.ellipses.push([p.x, p.y, e.rx.baseVal.value, e.ry.baseVal.value]);
      }
      for (const el of g.querySelectorAll('line, polyline, polygon, path')) {
        for (const run of outline(svg, el)) {
          for (const p of run) body.points.push([p.x, p.y]);
        }
      }
      report.bodies.push(body);
    }
    for (const g of svg.querySelectorAll('g.force[data-kind="gravity"]')) {
      const l = g.querySelector('line');
      if (!l) continue;
      const [a, b] = outline(svg, l)[0];
      report.gravity.push([a.x, a.y, b.x, b.y]);
    }
    out.push(report);
  }
  document.getElementById('result').textContent = JSON.stringify(out);
})();
