// Thinwall's HTML report viewer. Reads the data block (`tw-data`: the
// report's own JSON, the tessellated part and volumes, the colour table)
// and draws it with three.js (inline, `window.THREE`). No network.
(function () {
  'use strict';
  const T = window.THREE;
  const D = JSON.parse(document.getElementById('tw-data').textContent);
  const P = D.palette;
  const $ = (s) => document.querySelector(s);

  function fail(e) {
    const box = $('#error');
    box.hidden = false;
    box.textContent = 'The report viewer stopped: ' + (e && e.stack ? e.stack : e);
  }
  window.addEventListener('error', (ev) => fail(ev.error || ev.message));

  // ---------------------------------------------------------------- helpers
  function el(tag, attrs, ...kids) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'class') e.className = v;
      else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else if (v !== undefined && v !== null) e.setAttribute(k, v);
    }
    for (const k of kids) if (k !== null && k !== undefined) e.append(k);
    return e;
  }
  const SVGNS = 'http://www.w3.org/2000/svg';
  function sv(tag, attrs, ...kids) {
    const e = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else e.setAttribute(k, v);
    }
    for (const k of kids) e.append(k);
    return e;
  }
  const fmt = (x, d) => (typeof x === 'number' ? (Math.abs(x) >= 1e5 ? x.toExponential(3) : x.toFixed(d === undefined ? 2 : d)) : String(x));
  const mm = (x) => (x === undefined || x === null ? null : fmt(x) + ' mm');
  const vec = (v) => '(' + v.map((c) => fmt(c, 3)).join(', ') + ')';
  const colour = (name) => new T.Color(P[name] || P.other);
  const isWall = (k) => k === 'web' || k === 'rib' || k === 'flange' || k === 'wall';

  // ------------------------------------------------------------- the viewer
  const origin = (() => {
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (const f of D.part.faces) for (let i = 0; i < f.points.length; i += 3)
      for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], f.points[i + k]); hi[k] = Math.max(hi[k], f.points[i + k]); }
    return lo[0] === Infinity ? [0, 0, 0] : lo.map((l, k) => 0.5 * (l + hi[k]));
  })();

  // A Geometry (faces with their own points) as one three.js mesh with a
  // colour per vertex, plus its edges; `ranges[i]` are face i's vertices
  // and triangles, so a face can be repainted and a picked triangle named.
  function shape(geom, opacity) {
    let nv = 0, nt = 0;
    for (const f of geom.faces) { nv += f.points.length / 3; nt += f.triangles.length / 3; }
    const pos = new Float32Array(nv * 3), col = new Float32Array(nv * 3), idx = new Uint32Array(nt * 3);
    const ranges = [];
    let v = 0, t = 0;
    for (const f of geom.faces) {
      const n = f.points.length / 3, m = f.triangles.length / 3;
      for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) pos[3 * (v + i) + k] = f.points[3 * i + k] - origin[k];
      for (let i = 0; i < 3 * m; i++) idx[3 * t + i] = f.triangles[i] + v;
      ranges.push({ v0: v, nv: n, t0: t, nt: m });
      v += n; t += m;
    }
    const g = new T.BufferGeometry();
    g.setAttribute('position', new T.BufferAttribute(pos, 3));
    g.setAttribute('color', new T.BufferAttribute(col, 3));
    g.setIndex(new T.BufferAttribute(idx, 1));
    g.computeVertexNormals();
    g.computeBoundingSphere();
    const mat = new T.MeshLambertMaterial({
      vertexColors: true, side: T.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
      transparent: opacity < 1, opacity: opacity, depthWrite: opacity >= 1,
    });
    const mesh = new T.Mesh(g, mat);
    let ne = 0;
    for (const e of geom.edges) ne += Math.max(0, e.length / 3 - 1);
    const ep = new Float32Array(ne * 6);
    let j = 0;
    for (const e of geom.edges) for (let i = 0; i + 3 < e.length; i += 3) {
      for (let k = 0; k < 6; k++) ep[j++] = e[i + k] - origin[k % 3];
    }
    const eg = new T.BufferGeometry();
    eg.setAttribute('position', new T.BufferAttribute(ep, 3));
    const edges = new T.LineSegments(eg, new T.LineBasicMaterial({ color: 0x2a2f36, transparent: opacity < 1, opacity: Math.min(1, opacity + 0.25) }));
    const group = new T.Group();
    group.add(mesh, edges);
    // Where a label goes: the middle of the body (solid) with the largest box.
    const boxes = new Map();
    geom.faces.forEach((f, k) => {
      const b = boxes.get(f.body) || new T.Box3();
      const r = ranges[k];
      for (let i = r.v0; i < r.v0 + r.nv; i++) b.expandByPoint(new T.Vector3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]));
      boxes.set(f.body, b);
    });
    const bulk = (b) => { const s = b.getSize(new T.Vector3()); return s.x * s.y * s.z + 1e-9 * (s.x + s.y + s.z); };
    const centre = new T.Vector3();
    const largest = [...boxes.values()].filter((b) => !b.isEmpty()).sort((a, b) => bulk(b) - bulk(a))[0];
    if (largest) largest.getCenter(centre);
    return {
      group, mesh, edges, ranges, geom, centre,
      paint(fn) { // fn(face index) → THREE.Color
        for (let i = 0; i < ranges.length; i++) {
          const c = fn(i), r = ranges[i];
          for (let k = r.v0; k < r.v0 + r.nv; k++) { col[3 * k] = c.r; col[3 * k + 1] = c.g; col[3 * k + 2] = c.b; }
        }
        g.attributes.color.needsUpdate = true;
      },
      opacity(a) {
        mat.opacity = a; mat.transparent = a < 1; mat.depthWrite = a >= 1; mat.needsUpdate = true;
        edges.material.opacity = Math.min(1, a + 0.25); edges.material.transparent = a < 1;
      },
      faceOfTriangle(t) {
        let lo = 0, hi = ranges.length - 1;
        while (lo < hi) { const m = (lo + hi + 1) >> 1; if (ranges[m].t0 <= t) lo = m; else hi = m - 1; }
        return lo;
      },
    };
  }

  // A number drawn as a sprite that keeps its size on the screen.
  function label(text, bg) {
    const c = document.createElement('canvas');
    const ctx = c.getContext('2d');
    ctx.font = 'bold 40px sans-serif';
    const w = Math.ceil(ctx.measureText(text).width) + 24;
    c.width = w; c.height = 56;
    ctx.fillStyle = bg; ctx.strokeStyle = '#1d232b'; ctx.lineWidth = 3;
    ctx.beginPath(); ctx.roundRect(2, 2, w - 4, 52, 14); ctx.fill(); ctx.stroke();
    ctx.fillStyle = '#111'; ctx.font = 'bold 40px sans-serif'; ctx.textBaseline = 'middle'; ctx.textAlign = 'center';
    ctx.fillText(text, w / 2, 30);
    const tex = new T.CanvasTexture(c);
    const s = new T.Sprite(new T.SpriteMaterial({ map: tex, depthTest: false, sizeAttenuation: false }));
    s.scale.set(0.026 * w / 56, 0.026, 1);
    s.renderOrder = 10;
    return s;
  }

  class Viewer {
    constructor(box) {
      this.box = box;
      this.renderer = new T.WebGLRenderer({ antialias: true, alpha: true, preserveDrawingBuffer: true });
      this.renderer.setClearColor(0x000000, 0);
      this.renderer.setPixelRatio(window.devicePixelRatio || 1);
      box.prepend(this.renderer.domElement);
      this.scene = new T.Scene();
      this.camera = new T.PerspectiveCamera(30, 1, 0.1, 1000);
      this.camera.up.set(...D.up);
      this.scene.add(new T.AmbientLight(0xffffff, 1.1));
      this.sun = new T.DirectionalLight(0xffffff, 1.9);
      this.scene.add(this.sun);
      this.controls = new T.OrbitControls(this.camera, this.renderer.domElement);
      this.controls.addEventListener('change', () => this.render());
      this.pickables = [];
      this.onPick = null;
      new ResizeObserver(() => this.resize()).observe(box);
      let down = null;
      const canvas = this.renderer.domElement;
      canvas.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
      canvas.addEventListener('pointerup', (e) => {
        if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) this.pick(e);
        down = null;
      });
      this.resize();
    }
    resize() {
      const w = this.box.clientWidth || 800, h = this.box.clientHeight || 600;
      this.renderer.setSize(w, h, false);
      this.camera.aspect = w / h;
      this.camera.updateProjectionMatrix();
      this.render();
    }
    add(obj) { this.scene.add(obj); }
    look(dir) { // dir: from the target towards the camera, world frame
      const r = Math.max(D.size, 1e-6);
      const d = new T.Vector3(...dir).normalize();
      this.camera.near = r / 500; this.camera.far = r * 50;
      this.camera.position.copy(d.multiplyScalar(r * 1.9));
      this.controls.target.set(0, 0, 0);
      this.camera.updateProjectionMatrix();
      this.controls.update();
      this.render();
    }
    iso() {
      const [a, b] = D.across, u = D.up;
      this.look([0, 1, 2].map((k) => a[k] + b[k] + u[k])); // as the SVG picture
    }
    render() {
      if (this.pending) return;
      this.pending = true;
      requestAnimationFrame(() => {
        this.pending = false;
        this.sun.position.copy(this.camera.position).add(new T.Vector3(...D.up).multiplyScalar(D.size));
        this.renderer.render(this.scene, this.camera);
      });
    }
    pick(e) {
      const r = this.renderer.domElement.getBoundingClientRect();
      const ndc = new T.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
      const ray = new T.Raycaster();
      ray.setFromCamera(ndc, this.camera);
      const hits = ray.intersectObjects(this.pickables.filter((p) => p.mesh.visible && p.group.visible).map((p) => p.mesh), false);
      if (!hits.length || !this.onPick) return;
      const s = this.pickables.find((p) => p.mesh === hits[0].object);
      this.onPick(s, s.faceOfTriangle(hits[0].faceIndex));
    }
  }

  // --------------------------------------------------------- page structure
  const viewer = new Viewer($('#view3d'));
  const part = shape(D.part, 1);
  viewer.add(part.group);
  viewer.pickables.push(part);
  part.tag = { kind: 'part' };
  const faceIndex = new Map(); // "body:step" → index in D.part.faces
  D.part.faces.forEach((f, i) => faceIndex.set(f.body + ':' + f.step_id, i));
  const facesOf = (steps, body) => steps.map((s) => faceIndex.get((body || 0) + ':' + s)).filter((i) => i !== undefined);

  let mode = null; // the active tab's object
  let selected = null; // { key, ... } of the active tab
  // The classification's volumes sit inside the part: see through it.
  const state = { edges: true, part: true, xray: D.view === 'classification' };

  function status(text) { $('#status').textContent = text; }
  function legend(items) {
    const box = $('#legend');
    box.replaceChildren(...items.map(([name, c]) => el('div', null, el('span', { class: 'sw', style: 'background:' + c }), name)));
    box.hidden = items.length === 0;
  }
  function details(title, rows, extra) {
    const table = el('table');
    for (const [k, v] of rows) if (v !== undefined && v !== null && v !== '') table.append(el('tr', null, el('td', null, k), el('td', null, v)));
    $('#details').replaceChildren(el('h3', null, title), table, ...(extra || []));
  }
  function link(text, go) { return el('a', { onclick: go }, text); }
  function list(rows) { // rows: {key, id, what, colour, group?}
    const box = $('#list');
    const filter = $('#search').value.trim().toLowerCase();
    const kids = [];
    let group = null;
    for (const r of rows) {
      if (filter && !(r.id + ' ' + r.what).toLowerCase().includes(filter)) continue;
      if (r.group && r.group !== group) { group = r.group; kids.push(el('div', { class: 'group' }, group)); }
      const row = el('div', { class: 'row' + (selected && selected.key === r.key ? ' on' : ''), 'data-key': r.key, onclick: () => mode.select(r.key) },
        el('span', { class: 'sw', style: 'background:' + r.colour }), el('span', { class: 'id' }, r.id), el('span', { class: 'what' }, r.what));
      kids.push(row);
    }
    box.replaceChildren(...kids);
    const on = box.querySelector('.row.on');
    if (on) on.scrollIntoView({ block: 'nearest' });
  }

  // Faces in a lighter tone when something else is selected.
  const pale = (c) => c.clone().lerp(new T.Color(0xffffff), 0.55);

  // ------------------------------------------------------ stiffness features
  const rec = D.recognition;
  const stiff = rec ? rec.stiffness_features : [];
  const mach = rec ? rec.machining_features : [];
  const featureFaces = (f) => facesOf(f.faces.concat(f.top_end_faces || []), f.body);
  // The kind each face shows, by the report's own rule (svg::face_kinds).
  const faceKind = D.face_kinds || new Array(D.part.faces.length).fill(null);
  const kindColour = (i) => colour(faceKind[i] ? 'stiffness.' + faceKind[i] : 'other');

  // A curved wall's mid-surface in a line: "cylinder r 479.20 mm over 30.0°".
  function midSurface(m) {
    if (!m) return null;
    const over = m.angle_range_deg ? ' over ' + fmt(m.angle_range_deg[1] - m.angle_range_deg[0]) + '°' : '';
    const cone = m.half_angle_deg !== undefined ? ', half-angle ' + fmt(m.half_angle_deg) + '°' : '';
    const spread = m.thickness_range ? ', thickness ' + fmt(m.thickness_range[0]) + '–' + fmt(m.thickness_range[1]) + ' mm sampled' : '';
    return m.kind + (m.radius !== undefined ? ' r ' + mm(m.radius) : '') + over + cone + spread + ' (developed length and height)';
  }
  function stiffRows(f) {
    const access = (f.access || []).map((a, k) => ['side ' + (k + 1), (a.reachable ? 'reachable' : 'not reachable') + ' along ' + vec(a.direction) + ': ' + a.reason]);
    return [
      ['kind', f.kind], ['thin', f.thin === undefined ? null : (f.thin ? 'yes' : 'no')],
      ['thickness', mm(f.thickness)], ['thickness at foot / top', f.thickness_foot !== undefined ? mm(f.thickness_foot) + ' / ' + mm(f.thickness_top) : null],
      ['surface', midSurface(f.mid_surface)],
      [f.kind === 'web' ? 'span (largest unsupported radius)' : 'height', mm(f.height)], ['length', mm(f.length)], ['deflection', mm(f.deflection === undefined ? undefined : f.deflection)],
      ['through its base', f.other_side ? 'on the other side h ' + mm(f.other_side.height) + ', δ ' + mm(f.other_side.deflection) + ', h/t ' + fmt(f.other_side.slenderness) + (f.other_side.thin ? ', thin' : ', not thin') : null],
      [f.kind === 'web' ? 'slenderness (span/t)' : 'slenderness (h/t)', f.slenderness === undefined ? null : fmt(f.slenderness)], ['diameter', mm(f.diameter)], ['width', mm(f.width)],
      ['radius', mm(f.radius)], ['through', f.through === undefined ? null : String(f.through)], ['large', f.large === undefined ? null : String(f.large)],
      ['base', f.base], ['in wall', f.wall], ['note', f.model_note], ...access,
      ['faces', f.faces.length + ' (STEP ids ' + f.faces.slice(0, 12).join(', ') + (f.faces.length > 12 ? ', …' : '') + ')'],
    ];
  }
  // A hole's stages from the entry down, as the text report writes them.
  function holeStages(h) {
    const end = (e) => e.kind === 'blend' ? 'blend r ' + fmt(e.radius)
      : (e.kind === 'countersink' ? 'csk ' : 'chamfer ') + fmt(e.angle_deg) + '° Ø' + fmt(e.diameter);
    const s = [];
    if (h.entry) s.push(end(h.entry));
    for (const b of h.bores) s.push('Ø' + fmt(b.diameter) + ' x ' + fmt(b.depth));
    if (h.exit) s.push(end(h.exit));
    if (h.tip === 'flat') s.push('flat');
    else if (h.tip && h.tip.drill_point) s.push('point ' + fmt(h.tip.drill_point.angle_deg) + '°');
    return s.join(' > ');
  }
  function machRows(f) {
    return [
      ['kind', f.kind], ['catalogue', f.catalog], ['profile', f.profile], ['through', f.through === undefined ? null : String(f.through)],
      ['direction', f.direction ? vec(f.direction) : null], ['depth', mm(f.depth)], ['length', mm(f.length)], ['width', mm(f.width)],
      ['diameter', mm(f.diameter)], ['radius', mm(f.radius)], ['radii', f.radii && f.radii.length ? f.radii.map(fmt).join(', ') + ' mm' : null],
      ['corner radius', mm(f.corner_radius)], ['floor fillet', mm(f.floor_fillet)],
      ['wall draft', f.wall_draft_deg === undefined ? null : fmt(f.wall_draft_deg) + '°'],
      ['stages', f.hole ? holeStages(f.hole) : null],
      ['largest tool', mm(f.largest_tool_diameter)], ['reachable in the set-up', f.reachable === undefined ? null : String(f.reachable)],
      ['faces', f.faces.length + ' (STEP ids ' + f.faces.slice(0, 12).join(', ') + (f.faces.length > 12 ? ', …' : '') + ')'],
    ];
  }
  const relatedLinks = (ids, go) => ids && ids.length ? [el('p', null, 'Related: ', ...ids.flatMap((r, k) => [k ? ', ' : '', link(r, () => go(r))]))] : [];

  // A tab listing features whose faces are highlighted when chosen.
  function featureTab(name, features, colourOf, rows, legendItems) {
    return {
      name,
      enter() { part.group.visible = true; this.paint(); legend(legendItems()); this.list(); if (!selected) details(name, [['features', String(features.length)]], [el('p', { class: 'muted' }, 'Choose a feature in the list, in the picture or in the connection structure.')]); },
      list() { list(features.map((f) => ({ key: f.id, id: f.id, what: describe(f), colour: colourOf(f) }))); },
      paint() {
        const on = selected && selected.faces ? new Set(selected.faces) : null;
        part.paint((i) => (on ? (on.has(i) ? colour('selected') : pale(kindColour(i))) : kindColour(i)));
        viewer.render();
      },
      select(id) {
        const f = features.find((x) => x.id === id);
        if (!f) return;
        selected = { key: id, faces: featureFaces(f) };
        this.paint(); this.list(); graph.mark(id);
        details(f.id + ' — ' + f.kind, rows(f), relatedLinks(f.related, (r) => goTo(r)));
        status(f.id + ': ' + selected.faces.length + ' face(s) highlighted');
      },
      pickFace(i) { // the smallest feature of this tab with the face
        const f = features.filter((x) => featureFaces(x).includes(i)).sort((a, b) => a.faces.length - b.faces.length)[0];
        if (f) this.select(f.id); else faceInfo(i);
      },
    };
  }
  function describe(f) {
    const parts = [f.kind];
    if (f.thin !== undefined) parts.push(f.thin ? 'thin' : 'thick');
    if (f.thickness !== undefined) parts.push('t ' + fmt(f.thickness));
    if (f.height !== undefined) parts.push('h ' + fmt(f.height));
    if (f.diameter !== undefined) parts.push('Ø' + fmt(f.diameter));
    if (f.depth !== undefined) parts.push('depth ' + fmt(f.depth));
    if (f.catalog) parts.push(f.catalog);
    return parts.join(' · ');
  }
  function faceInfo(i) {
    const f = D.part.faces[i];
    selected = { key: null, faces: [i] };
    mode.paint && mode.paint();
    const face = rec ? rec.faces.find((x) => x.step_id === f.step_id && x.body === f.body) : null;
    details('Face #' + f.step_id, [['surface', f.surface], ['body', String(f.body)], ['area', face ? fmt(face.area) + ' mm²' : null], ['name', face && face.name], ['tessellation', f.issue]]);
  }
  const kindLegend = () => {
    const seen = new Set(faceKind.filter((k) => k));
    return [...seen].sort().map((k) => [k, P['stiffness.' + k]]).concat([['no feature / shared', P.other]]);
  };

  // ------------------------------------------------- the connection graph
  const graph = (() => {
    let nodes = new Map(); // id → <g>
    function draw(box) {
      const conns = (rec && rec.connections) || [];
      const ids = new Set(stiff.filter((f) => isWall(f.kind)).map((f) => f.id));
      const ends = (c) => (c.kind === 'base_leaf' ? [c.base, c.leaf] : c.features || []);
      for (const c of conns) for (const i of ends(c)) ids.add(i);
      const byId = new Map(stiff.map((f) => [f.id, f]));
      const leafOf = conns.filter((c) => c.kind === 'base_leaf');
      const crossing = conns.filter((c) => c.kind !== 'base_leaf');
      // Depth: longest base-leaf chain from a root (guarded against cycles).
      const depth = new Map([...ids].map((i) => [i, 0]));
      for (let round = 0; round < ids.size; round++) {
        let moved = false;
        for (const c of leafOf) if (depth.get(c.leaf) < depth.get(c.base) + 1 && depth.get(c.base) + 1 < ids.size) { depth.set(c.leaf, depth.get(c.base) + 1); moved = true; }
        if (!moved) break;
      }
      const rows = [];
      for (const [i, d] of depth) (rows[d] = rows[d] || []).push(i);
      const num = (s) => parseInt(s.replace(/^\D+/, ''), 10) || 0;
      const x = new Map();
      const W = Math.max(box.clientWidth - 36, 300), dy = 58;
      rows.forEach((row, d) => {
        const parentX = (i) => { const ps = leafOf.filter((c) => c.leaf === i && x.has(c.base)).map((c) => x.get(c.base)); return ps.length ? ps.reduce((a, b) => a + b) / ps.length : 0; };
        row.sort((a, b) => (d ? parentX(a) - parentX(b) : 0) || a.replace(/\d+/, '').localeCompare(b.replace(/\d+/, '')) || num(a) - num(b));
        const step = Math.min(W / (row.length + 1), 90);
        const left = (W - step * (row.length - 1)) / 2;
        row.forEach((i, k) => x.set(i, left + k * step));
      });
      const y = (i) => 26 + depth.get(i) * dy;
      const H = 26 + (rows.length - 1) * dy + 34;
      const svg = sv('svg', { class: 'graph', width: W, height: Math.max(H, 60), viewBox: '0 0 ' + W + ' ' + Math.max(H, 60) });
      for (const c of leafOf) if (x.has(c.base) && x.has(c.leaf)) svg.append(sv('line', { x1: x.get(c.base), y1: y(c.base), x2: x.get(c.leaf), y2: y(c.leaf), stroke: '#56606c', 'stroke-width': 1.6 }));
      for (const c of crossing) {
        const [a, b] = ends(c);
        if (!x.has(a) || !x.has(b)) continue;
        const mx = (x.get(a) + x.get(b)) / 2, my = Math.min(y(a), y(b)) - 22 - 0.08 * Math.abs(x.get(a) - x.get(b));
        svg.append(sv('path', { d: `M${x.get(a)},${y(a)} Q${mx},${my} ${x.get(b)},${y(b)}`, fill: 'none', stroke: '#c0562b', 'stroke-dasharray': '5 4', 'stroke-width': 1.4 }));
      }
      nodes = new Map();
      for (const i of ids) {
        const f = byId.get(i);
        const fill = f ? P['stiffness.' + f.kind] : P.other;
        const thin = f && f.thin;
        const g = sv('g', { class: 'node', transform: `translate(${x.get(i)},${y(i)})`, onclick: () => goTo(i) },
          sv('circle', { r: 15, fill, stroke: thin ? '#1d232b' : '#8a929c', 'stroke-width': thin ? 2 : 1 }),
          sv('text', { 'text-anchor': 'middle', dy: 4 }, i));
        const t = sv('title'); t.textContent = f ? describe(f) : i; g.append(t);
        nodes.set(i, g);
        svg.append(g);
      }
      const key = el('div', { class: 'muted' }, conns.length ? 'Base above leaf (solid); crossing walls (dashed, orange); a dark ring marks a thin wall. Click a node.' : 'No connections between walls.');
      box.append(el('h4', null, 'Connection structure'), key, svg);
    }
    function mark(id) { for (const [i, g] of nodes) g.classList.toggle('on', i === id); }
    return { draw, mark };
  })();

  // ------------------------------------------------------------ the plan
  // One set-up's plan (`plan`: the page's, or one of its `then`) with its
  // features' `volumes`, under the tab `name`.
  function planTab(name, plan, volumes) {
    const feats = plan.machining_features;
    const order = plan.feature_sequence.order;
    const rank = new Map(order.map((id, k) => [id, k]));
    const byId = new Map(feats.map((f) => [f.id, f]));
    const sorted = order.map((id) => byId.get(id)).filter(Boolean);
    const vols = new Map();
    for (const v of volumes) if (v.geometry) {
      const s = shape(v.geometry, 0.45);
      s.tag = { kind: 'volume', id: v.id };
      s.group.visible = false;
      viewer.add(s.group); viewer.pickables.push(s);
      vols.set(v.id, s);
    }
    const labels = new T.Group();
    viewer.add(labels);
    const walls = [...new Set(feats.filter((f) => f.owner).map((f) => f.owner))].sort((a, b) => a.localeCompare(b, undefined, { numeric: true }));
    // More volumes than this: only the current one is numbered.
    const LABELS = 60;
    let step = 0, wall = '', timer = null;
    const classColour = (f) => P['plan.' + f.size_class] || P.other;
    const box = $('#bottom');
    const slider = el('input', { type: 'range', min: 0, max: sorted.length, value: 0, oninput: (e) => go(+e.target.value) });
    const now = el('span', { class: 'now' });
    const wallSel = el('select', { onchange: (e) => { wall = e.target.value; go(first()); } }, el('option', { value: '' }, 'every wall'), ...walls.map((w) => el('option', { value: w }, 'wall ' + w + ' (fig. 4.1 numbers)')));
    const play = el('button', { onclick: () => { if (timer) { clearInterval(timer); timer = null; play.textContent = '▶ play'; } else { play.textContent = '❚❚ pause'; timer = setInterval(() => { if (step >= sorted.length) { clearInterval(timer); timer = null; play.textContent = '▶ play'; } else go(next(1)); }, 700); } } }, '▶ play');
    // With a wall chosen, the steps are its own features in the order.
    const mine = (k) => !wall || (sorted[k] && sorted[k].owner === wall);
    function next(d) {
      let k = step + d;
      while (k >= 0 && k < sorted.length && !mine(k)) k += d;
      return k < 0 ? step : k;
    }
    function first() { let k = 0; while (k < sorted.length && !mine(k)) k++; return k; }
    function go(k) {
      step = Math.max(0, Math.min(sorted.length, k));
      slider.value = step;
      const cur = sorted[step];
      selected = cur ? { key: cur.id } : null;
      now.textContent = cur ? `${step + 1} / ${sorted.length}: ${cur.id} — ${what(cur)}` : `all ${sorted.length} removed: the finished part`;
      redraw();
      if (cur) showFeature(cur);
    }
    function what(f) {
      const bits = [f.size_class.replace('_', ' ')];
      if (f.owner) bits.push('of ' + f.owner + (f.side !== undefined ? ' side ' + (f.side + 1) : ''));
      if (f.step) bits.push('step ' + f.step);
      if (f.type) bits.push(f.type.replace('_', ' '));
      bits.push(fmt(f.volume_mm3, 0) + ' mm³');
      return bits.join(' · ');
    }
    function redraw() {
      labels.clear();
      const cur = sorted[step];
      let shown = 0;
      for (const f of sorted) {
        const s = vols.get(f.id);
        if (!s) continue;
        const r = rank.get(f.id);
        const inWall = !wall || f.owner === wall;
        s.group.visible = inWall && r >= step;
        if (!s.group.visible) continue;
        shown++;
        const c = f === cur ? colour('plan.current') : new T.Color(classColour(f));
        s.paint(() => c);
        s.opacity(f === cur ? 0.9 : 0.42);
      }
      for (const f of sorted) {
        const s = vols.get(f.id);
        if (!s || !s.group.visible) continue;
        if (shown > LABELS && f !== cur) continue;
        const n = wall && f.step ? String(f.step) : String(rank.get(f.id) + 1);
        const l = label(n, f === cur ? P['plan.current'] : '#ffffff');
        l.position.copy(s.centre);
        labels.add(l);
      }
      const wf = wall ? stiff.find((x) => x.id === wall) : null;
      const on = wf ? new Set(featureFaces(wf)) : null;
      part.paint((i) => (on && on.has(i) ? colour('selected') : kindColour(i)));
      status((wall ? 'wall ' + wall + ': ' : '') + shown + ' machining feature(s) still to remove' + (shown > LABELS ? ' (numbers only on the current one: choose a wall to number its features)' : ''));
      viewer.render();
      list(sorted.filter((f) => !wall || f.owner === wall).map((f) => ({ key: f.id, id: (rank.get(f.id) + 1) + '. ' + f.id, what: what(f), colour: classColour(f), group: f.owner ? null : null })));
    }
    function showFeature(f) {
      selected = { key: f.id };
      const rel = plan.feature_sequence.relations.filter((r) => r.before === f.id || r.after === f.id);
      const vol = volumes.find((v) => v.id === f.id);
      details(f.id + ' — ' + f.size_class.replace('_', ' '), [
        ['order', (rank.get(f.id) + 1) + ' of ' + sorted.length], ['owner', f.owner], ['side', f.side === undefined ? null : String(f.side + 1)],
        ['step (fig. 4.1)', f.step === undefined ? null : String(f.step)], ['type', f.type], ['product adjacency', f.product_adjacency],
        ['z range', fmt(f.z_range[0]) + ' – ' + fmt(f.z_range[1]) + ' mm'], ['volume', fmt(f.volume_mm3, 1) + ' mm³'],
        ['designed box', f.box_volume_mm3 === undefined ? null : fmt(f.box_volume_mm3, 1) + ' mm³'], ['reachable from up', String(f.reachable)],
        ['access', f.access ? vec(f.access) : null], ['solids', String(f.solids.length)], ['part faces touched', String(f.faces.length)],
        ['picture', vol && vol.note], ['why unknown', f.reason],
      ], [
        ...(f.changes || []).map((c) => el('p', { class: 'muted' }, c)),
        el('p', null, el('b', null, 'Before / after: ')),
        ...rel.slice(0, 30).map((r) => el('div', null, link(r.before === f.id ? '→ ' + r.after : '← ' + r.before, () => go(rank.get(r.before === f.id ? r.after : r.before))), ' ', el('span', { class: 'muted' }, r.why))),
      ]);
    }
    const controls = el('div', null, el('h4', null, 'Machining-feature order: step through it'),
      el('div', { class: 'controls' },
        el('button', { onclick: () => go(first()), title: 'first' }, '«'), el('button', { onclick: () => go(next(-1)) }, '◀'), slider,
        el('button', { onclick: () => go(next(1)) }, '▶'), el('button', { onclick: () => go(sorted.length), title: 'all removed' }, '»'), play, wallSel),
      now,
      el('div', { class: 'muted' }, plan.removal.unavailable ? 'No removal plan: ' + plan.removal.unavailable :
        `Up ${vec(plan.up)}. Volumes still to remove are drawn in their class colour, the current one in orange, numbered in the order (with a wall chosen, by their step in its approach, as Popma fig. 4.1). Stock ${plan.removal.stock}, ${fmt(plan.removal.removed_volume_mm3, 0)} mm³ removed in ${feats.length} features` +
        (plan.removal.cleared_before_mm3 ? `; ${fmt(plan.removal.cleared_before_mm3, 0)} mm³ taken by the set-ups before` : '') +
        (plan.supported_webs ? `; webs supported by the material under them (no step layers here): ${plan.supported_webs.join(' ')}` : '') + '.'),
      D.plan.then && plan === D.plan ? el('div', { class: 'muted' }, (D.plan.proposal ? 'Set-ups proposed: ' + D.plan.proposal.why.join(' · ') + ' ' : '') + (D.plan.residue ? 'No set-up reaches ' + fmt(D.plan.residue.volume_mm3, 1) + ' mm³.' : '')) : '');
    controls.hidden = true;
    box.append(controls);
    const legendItems = ['large', 'small', 'bulk', 'other_setup', 'detail'].filter((c) => feats.some((f) => f.size_class === c)).map((c) => [c.replace('_', ' '), P['plan.' + c]]).concat([['current', P['plan.current']]]);
    return {
      name,
      enter() { controls.hidden = false; part.group.visible = state.part; for (const s of vols.values()) s.group.visible = true; labels.visible = true; legend(legendItems); go(step); },
      leave() { controls.hidden = true; for (const s of vols.values()) s.group.visible = false; labels.visible = false; },
      list() { redraw(); },
      paint() { redraw(); },
      select(id) { if (rank.has(id)) go(rank.get(id)); },
      setWall(w) { wall = walls.includes(w) ? w : ''; wallSel.value = wall; go(first()); },
      go,
      pickFace(i, s) { if (s && s.tag.kind === 'volume') this.select(s.tag.id); else faceInfo(i); },
    };
  }

  // --------------------------------------------------- the classification
  function classificationTab() {
    const rep = D.classification;
    const vols = D.volumes.map((v, k) => {
      const s = shape(v.geometry, 0.5);
      s.tag = { kind: 'volume', id: String(k) };
      viewer.add(s.group); viewer.pickables.push(s);
      return s;
    });
    const typeColour = (c) => (c.type === 'unknown' ? P.other : P['machining.' + c.type] || P['plan.bulk']);
    return {
      name: 'Volumes',
      enter() {
        legend([['closed face (touches the part or a volume still there)', P['volume.closed']], ['open face', P['volume.open']], ['part face it touches', P['volume.touched']]]);
        this.list(); this.paint();
        if (!selected) details('Classification', [['volumes', String(rep.volumes.length)], ['up', vec(rep.up)]], [el('p', { class: 'muted' }, 'Choose a volume: its closed faces are red, its open faces green.')]);
      },
      list() { list(rep.volumes.map((c, k) => ({ key: String(k), id: String(k), what: c.type + ' · ' + c.product_adjacency + ' · ' + c.name.split('/').pop(), colour: typeColour(c) }))); },
      paint() {
        const k = selected && selected.key !== null ? +selected.key : -1;
        vols.forEach((s, j) => {
          const c = rep.volumes[j];
          const byStep = new Map(c.faces.map((f) => [f.step_id, f]));
          if (k < 0 || j === k) {
            s.paint((i) => { const f = byStep.get(D.volumes[j].geometry.faces[i].step_id); return colour(f && f.closed ? 'volume.closed' : 'volume.open'); });
            s.opacity(j === k ? 0.95 : 0.5);
            s.group.visible = true;
          } else {
            s.paint(() => new T.Color(typeColour(c))); s.opacity(0.12); s.group.visible = true;
          }
        });
        const touched = new Set();
        if (k >= 0) for (const f of rep.volumes[k].faces) for (const t of f.touches) if (t.kind === 'part') for (const i of facesOf([t.step_id], 0)) touched.add(i);
        part.paint((i) => (touched.has(i) ? colour('volume.touched') : colour('other')));
        viewer.render();
      },
      select(key) {
        const c = rep.volumes[+key];
        if (!c) return;
        selected = { key };
        this.paint(); this.list();
        const table = el('table', null, el('tr', null, el('td', null, 'face'), el('td', null, 'role · surface · closed · touches')));
        for (const f of c.faces) table.append(el('tr', null, el('td', null, '#' + f.step_id), el('td', null, `${f.role} · ${f.surface} · ${f.closed ? 'closed' : 'open'} · ${f.touches.map((t) => (t.kind === 'part' ? 'part #' + t.step_id : 'volume ' + t.index)).join(', ') || '—'}`)));
        details(c.name.split('/').pop() + ' — ' + c.type, [['type', c.type], ['why unknown', c.reason], ['product adjacency', c.product_adjacency], ['tool direction', vec(c.direction)], ['bottom open', String(c.bottom_open)], ['depth', mm(c.depth)], ['length', mm(c.length)], ['width', mm(c.width)], ['corner radii', c.corner_radii.length ? c.corner_radii.map(fmt).join(', ') + ' mm' : null]], [el('h3', null, 'Faces'), table]);
      },
      pickFace(i, s) { if (s && s.tag.kind === 'volume') this.select(s.tag.id); else faceInfo(i); },
    };
  }

  // ------------------------------------------------- access: shared marks
  // Lines drawn over the part (outlines, directions), cleared per choice.
  function overlay() {
    const marks = new T.Group();
    viewer.add(marks);
    const line = (pts, colour) => {
      const g = new T.BufferGeometry();
      const arr = new Float32Array(pts.length * 3);
      pts.forEach((p, k) => { for (let j = 0; j < 3; j++) arr[3 * k + j] = p[j] - origin[j]; });
      g.setAttribute('position', new T.BufferAttribute(arr, 3));
      return new T.LineSegments(g, new T.LineBasicMaterial({ color: colour, depthTest: false }));
    };
    const rings = (list, colour) => {
      for (const ring of list || []) {
        const pts = [];
        for (let k = 0; k < ring.length; k++) pts.push(ring[k], ring[(k + 1) % ring.length]);
        marks.add(line(pts, colour));
      }
    };
    return { marks, line, rings };
  }

  // Faces by body and STEP id in `index`, coloured by `tint`; the rest
  // grey, and all but the chosen pale.
  function paintFaces(index, tint) {
    const on = selected && selected.faces ? new Set(selected.faces) : null;
    part.paint((i) => {
      const fd = D.part.faces[i];
      const f = index.get(fd.body + ':' + fd.step_id);
      const c = f ? new T.Color(tint(f)) : colour('other');
      return on && !on.has(i) ? pale(c) : c;
    });
    viewer.render();
  }
  function pickIndexed(tab, index, i) {
    const fd = D.part.faces[i];
    const key = fd.body + ':' + fd.step_id;
    if (index.has(key)) tab.select(key); else faceInfo(i);
  }

  // ------------------------------------------------- reach (access)
  function reachTab() {
    const rep = D.access;
    const faces = rep.faces;
    const index = new Map(faces.map((f) => [f.body + ':' + f.face, f]));
    const WHOLE = 1 - 1e-4;
    const band = (f) => (f.fraction >= WHOLE ? 'whole' : f.fraction >= 0.75 ? 'most' : f.fraction > 0 ? 'part' : 'none');
    const tint = (f) => P['reach.' + band(f)];
    const { marks, rings } = overlay();
    const tool = rep.reach.tool;
    const toolText = 'Ø' + fmt(tool.diameter) + ' mm, cutting ' + fmt(tool.cutting_length) + ' mm, holder Ø' + fmt(tool.holder_diameter) + ' mm';
    const machine = rep.reach.machine.class === 'five_axis' ? 'five axes, tilt ≤ ' + fmt(rep.reach.machine.tilt_limit_deg) + '°' : 'three axes';
    // Each machining feature's largest tool, beside the floor's own bound.
    function featureTools() {
      const feats = rep.features || [];
      if (!feats.length) return [];
      const dia = (d) => (d != null ? 'Ø' + fmt(d) : '—');
      const table = el('table', null, el('tr', null, el('td', null, 'feature'), el('td', null, 'largest tool (face bounding it)'), el('td', null, 'fits the floor')));
      for (const m of feats) table.append(el('tr', null, el('td', null, m.feature + ' ' + m.kind), el('td', null, dia(m.largest_tool_mm) + (m.bound ? ' (its ' + m.bound.replace(/_/g, ' ') + ')' : m.bounded_by != null ? ' (#' + m.bounded_by + ')' : '')), el('td', null, dia(m.fits_mm))));
      return [el('h3', null, 'Largest tool reaching each machining feature whole'), table];
    }
    return {
      name: 'Reach',
      enter() {
        part.group.visible = true;
        legend([['reached whole', P['reach.whole']], ['75 % or more', P['reach.most']], ['partly', P['reach.part']], ['not reached', P['reach.none']]]);
        this.list(); this.paint();
        if (!selected) details('Reach', [['tool', toolText], ['machine', machine], ['faces', String(faces.length)], ['reached whole', String(faces.filter((f) => f.fraction >= WHOLE).length)], ['not reached', String(faces.filter((f) => f.fraction <= 0).length)]], [el('p', { class: 'muted' }, 'Faces coloured by the share the tool reaches without the cutter or holder cutting into the part. Choose a face: the part it does not reach is outlined red.'), ...featureTools()]);
      },
      leave() { marks.clear(); },
      list() {
        const order = [...faces].sort((a, b) => a.fraction - b.fraction || a.face - b.face);
        list(order.map((f) => ({ key: f.body + ':' + f.face, id: '#' + f.face, what: f.contact + ' · ' + fmt(100 * f.fraction, 1) + ' %' + (f.largest_tool_mm != null ? ' · largest Ø' + fmt(f.largest_tool_mm) : ''), colour: tint(f) })));
      },
      paint() { paintFaces(index, tint); },
      select(key) {
        const f = index.get(key);
        if (!f) return;
        selected = { key, faces: [faceIndex.get(key)] };
        this.paint(); this.list();
        marks.clear(); rings(f.unreachable, 0xd0201a); viewer.render();
        const table = el('table', null, el('tr', null, el('td', null, 'face'), el('td', null, 'tool part · unreached mm²')));
        for (const b of f.blocked_by || []) table.append(el('tr', null, el('td', null, '#' + b.face), el('td', null, b.by + ' · ' + fmt(b.unreachable_mm2))));
        details('Face #' + f.face + ' — ' + f.contact, [['area', fmt(f.area_mm2) + ' mm²'], ['reached', fmt(100 * f.fraction, 1) + ' %'], ['not reached', fmt(f.unreachable_mm2) + ' mm²'], ['tool', toolText], ['tilt', f.tilt_deg ? fmt(f.tilt_deg) + '°' : null], ['largest tool reaching it whole', f.largest_tool_mm != null ? 'Ø' + fmt(f.largest_tool_mm) + ' mm' : null], ['note', f.note]], (f.blocked_by || []).length ? [el('h3', null, 'In the way'), table] : []);
      },
      pickFace(i) { pickIndexed(this, index, i); },
    };
  }

  // ------------------------------------------------- flank milling (access)
  function accessTab() {
    const rep = D.access;
    const planar = rep.planar_faces;
    const index = new Map(planar.map((f) => [f.body + ':' + f.face, f]));
    const state = (f) => (f.nature === 'closed' ? 'closed' : f.advisable ? 'advisable' : f.visibility > 0.5 ? 'partial' : 'blocked');
    const tint = (f) => P['access.' + state(f)];
    const { marks, line, rings } = overlay();
    function showMarks(f) {
      marks.clear();
      if (!f) return;
      // The G-zone's outlines, and each direction used as a line into the
      // face's middle (the tool's body comes from its far end).
      rings(f.g_zone, 0xd0201a);
      const i = faceIndex.get(f.body + ':' + f.face);
      const pts = D.part.faces[i].points;
      const c = [0, 0, 0];
      for (let k = 0; k < pts.length; k += 3) for (let j = 0; j < 3; j++) c[j] += pts[k + j] / (pts.length / 3);
      const len = 0.25 * D.size;
      for (const u of f.used) marks.add(line([c.map((x, j) => x - u.direction[j] * len), c], 0x1b62c4));
      viewer.render();
    }
    return {
      name: 'Flank milling',
      enter() {
        part.group.visible = true;
        legend([['advisable (≥ ' + Math.round(100 * rep.flank_milling.threshold) + ' % reached)', P['access.advisable']], ['partly reached', P['access.partial']], ['mostly blocked', P['access.blocked']], ['closed face', P['access.closed']], ['not planar', P.other]]);
        this.list(); this.paint();
        if (!selected) details('Flank milling', [['planar faces', String(planar.length)], ['advisable', String(planar.filter((f) => f.advisable).length)], ['tool', 'Ø' + fmt(rep.flank_milling.tool_diameter) + ' mm' + (rep.flank_milling.tool_radius ? ', radius widens the zones' : '')], ['not yet', rep.not_yet.join('; ')]], [el('p', { class: 'muted' }, 'Choose a face: its unreachable G-zone is outlined red, the directions used are blue lines (the tool comes in along them).')]);
      },
      leave() { marks.clear(); },
      list() { list(planar.map((f) => ({ key: f.body + ':' + f.face, id: '#' + f.face, what: f.nature.replace('_', '-') + ' · ' + fmt(100 * f.visibility, 1) + ' % · ' + (f.advisable ? 'advisable' : 'not advisable'), colour: tint(f) }))); },
      paint() { paintFaces(index, tint); },
      select(key) {
        const f = index.get(key);
        if (!f) return;
        selected = { key, faces: [faceIndex.get(key)] };
        this.paint(); this.list(); showMarks(f);
        const table = el('table', null, el('tr', null, el('td', null, 'direction'), el('td', null, 'priority · rule · L-zone')));
        for (const c of f.candidates) table.append(el('tr', null, el('td', null, vec(c.direction)), el('td', null, c.priority + ' · ' + c.rule + ' (edge #' + c.edge + ') · ' + fmt(c.l_zone_mm2) + ' mm²')));
        details('Face #' + f.face + ' — ' + f.nature.replace('_', '-'), [['area', fmt(f.area_mm2) + ' mm²'], ['reached', fmt(100 * f.visibility, 1) + ' %'], ['G-zone (unreached)', fmt(f.g_zone_mm2) + ' mm²'], ['verdict', f.advisable ? 'advisable for flank milling' : 'not advisable'], ['obstacles within reach', String(f.obstacles)], ['closed edges', f.edges.filter((e) => e.sharpness.includes('closed')).length + ' of ' + f.edges.length], ['directions used', f.used.map((u) => vec(u.direction)).join(' ')], ['note', f.note]], [el('h3', null, 'Candidates, in the order tried'), table]);
      },
      pickFace(i) { pickIndexed(this, index, i); },
    };
  }

  // ------------------------------------------------- operations
  // One set-up's sheet (`side`: the report's first set-up, or one of
  // `then`, the set-ups after it), under the tab `name`.
  function operationsTab(name, side) {
    const rep = D.operations;
    const ops = side.setup.operations;
    const [o3, fx, fy, fz] = side.frame;
    // A point of the removal frame (x, y at height z) in the part's space.
    const world = (p, z) => [0, 1, 2].map((j) => o3[j] + p[0] * fx[j] + p[1] * fy[j] + z * fz[j]);
    const tint = (o) => P['ops.' + o.stage];
    const { marks, line, rings } = overlay();
    const key = (o) => String(o.step);
    function showMarks(o) {
      marks.clear();
      if (!o) return;
      for (const p of o.passes) {
        const layer = side.setup.layers[p.layer];
        for (const j of p.fields) {
          const f = layer.fields[j];
          // Each contour at the pass's bottom and top, joined by a few
          // uprights: the slab the pass takes.
          const hex = new T.Color(tint(o)).getHex();
          for (const c of [f.outer, ...f.islands]) {
            rings([c.points.map((q) => world(q, p.z_bottom_mm)), c.points.map((q) => world(q, p.z_top_mm))], hex);
            const every = Math.max(1, Math.ceil(c.points.length / 24));
            const ups = [];
            c.points.forEach((q, k) => { if (k % every === 0) ups.push(world(q, p.z_bottom_mm), world(q, p.z_top_mm)); });
            marks.add(line(ups, hex));
          }
        }
      }
      for (const h of side.setup.holes.filter((h) => (o.holes || []).includes(h.id))) {
        marks.add(line([world(h.centre, h.z_top_mm), world(h.centre, h.z_bottom_mm)], new T.Color(tint(o)).getHex()));
      }
      viewer.render();
    }
    const what = (o) => o.stage.replace('_', '-') + ' · ' + o.tool + (o.feature ? ' · ' + o.feature : '') + ((o.finishes || []).length ? ' · ' + o.finishes.join(' ') + (o.corners ? ' (corners)' : '') : '') + ' · ' + fmt(o.z_top_mm, 1) + '..' + fmt(o.z_bottom_mm, 1) + ' · ' + fmt(o.time_min) + ' min';
    return {
      name,
      enter() {
        part.group.visible = true;
        part.opacity(0.28);
        part.paint(() => colour('other'));
        legend([['rough', P['ops.rough']], ['semi-finish (rest)', P['ops.semi_finish']], ['finish (walls)', P['ops.finish_walls']], ['finish (floor)', P['ops.finish']], ['drill', P['ops.drill']], ['finish by radii', P['ops.finish_radii']]]);
        this.list();
        if (!selected) details(name, [['tools', rep.tools.source + ' (' + rep.tools.tools.length + ')'], ['operations', String(ops.length)], ['up', vec(side.up)], ['tool changes', side.setup.tool_changes + ' (' + side.setup.plain_tool_changes + ' in the plain order)'], ['time', fmt(side.setup.time_min, 1) + ' min'], ['tools in order', (side.setup.tool_sheet || []).map(u => u.tool + ' (' + u.stages.join(', ') + '; ' + u.operations + ' op., loaded ' + u.loads + '×, ' + fmt(u.time_min, 2) + ' min)').join(' → ')], ['step approach', side.setup.layers.some(l => l.step_limit_mm != null) ? side.setup.layers.filter(l => l.step_limit_mm != null).length + ' layer(s) beside thin walls, none deeper than h_RF (at least ' + fmt(Math.min(...side.setup.layers.filter(l => l.step_limit_mm != null).map(l => l.step_limit_mm))) + ' mm), each pass finishing its walls' : null], ['rest no tool reaches', fmt(side.setup.rest.reduce((s, r) => s + r.area_mm2 - (r.below_minimum ? r.below_minimum.area_mm2 : 0), 0)) + ' mm²'], ['rest under the minimum share', side.setup.rest.some(r => r.below_minimum) ? fmt(side.setup.rest.reduce((s, r) => s + (r.below_minimum ? r.below_minimum.area_mm2 : 0), 0)) + ' mm² (' + fmt(rep.tools.min_share_mm2, 1) + ' mm² per field and layer)' : null], ['another set-up', (side.setup.other_setup || []).join(' ')], ['left to another set-up', side.setup.out_of_reach_mm3 ? fmt(side.setup.out_of_reach_mm3, 1) + ' mm³ under the part' : null], ['taken by the set-ups before', side.setup.cleared_before_mm3 ? fmt(side.setup.cleared_before_mm3, 1) + ' mm³' : null], ['cut again (at most)', side.setup.recut_mm3 ? fmt(side.setup.recut_mm3, 1) + ' mm³' : null], ['no set-up reaches', rep.residue && side === rep ? fmt(rep.residue.volume_mm3, 1) + ' mm³' + (rep.residue.faces.length ? ' round #' + rep.residue.faces.join(' #') : '') : null], ['set-ups proposed', rep.proposal && side === rep ? rep.proposal.why.join(' · ') : null], ['not yet', rep.not_yet.join('; ')]], [el('p', { class: 'muted' }, 'Operations in their order. Choose one: the cutter fields of its passes are drawn at their levels (drills as their holes\' axes).')]);
        viewer.render();
      },
      leave() { marks.clear(); part.opacity(state.xray ? 0.28 : 1); },
      list() { list(ops.map((o) => ({ key: key(o), id: String(o.step), what: what(o), colour: tint(o) }))); },
      paint() {},
      select(k) {
        const o = ops.find((x) => key(x) === k);
        if (!o) return;
        selected = { key: k };
        this.list(); showMarks(o);
        const g = o.regions;
        const table = el('table', null, el('tr', null, el('td', null, 'layer'), el('td', null, 'z mm · area mm² · volume mm³ · min')));
        for (const p of o.passes) table.append(el('tr', null, el('td', null, String(p.layer + 1)), el('td', null, fmt(p.z_top_mm, 1) + '..' + fmt(p.z_bottom_mm, 1) + ' · ' + fmt(p.area_mm2, 1) + ' · ' + fmt(p.volume_mm3, 0) + ' · ' + fmt(p.time_min))));
        details('Step ' + o.step + ' — ' + o.stage.replace('_', '-') + ' with ' + o.tool, [['tool', o.tool + ', Ø' + fmt(o.diameter_mm, 1) + ' mm'], ['feature', o.feature], ['z', fmt(o.z_top_mm) + ' .. ' + fmt(o.z_bottom_mm) + ' mm'], ['area', fmt(o.area_mm2, 1) + ' mm²'], ['regions', g ? 'boundary ' + fmt(g.boundary_mm2, 1) + ' · full cut ' + fmt(g.full_cut_mm2, 1) + ' · roughing ' + fmt(g.roughing_mm2, 1) + ' mm²' : null], ['adjacency', o.adjacency.replace(/_/g, ' ')], ['volume', fmt(o.volume_mm3, 0) + ' mm³'], ['time', fmt(o.time_min) + ' min'], ['drilling', o.drill ? o.drill + ': ' + o.holes.join(' ') : null], ['finishes', (o.finishes || []).length ? o.finishes.join(' ') + (o.corners ? ': their corners' : ': walls, corners and floor fillets') : null], ['after steps', o.after.join(', ') || '—']], o.passes.length ? [el('h3', null, 'Passes'), table] : []);
      },
      pickFace(i) { faceInfo(i); },
    };
  }

  // ------------------------------------------------------------ assemble
  const tabs = [];
  if (rec && D.view !== 'plan') {
    tabs.push(featureTab('Stiffness features', stiff, (f) => P['stiffness.' + f.kind] || P.other, stiffRows, kindLegend));
    tabs.push(featureTab('Machining features', mach, (f) => P['machining.' + f.kind] || P.other, machRows,
      () => [...new Set(mach.map((f) => f.kind))].sort().map((k) => [k, P['machining.' + k]])));
  }
  if (D.view === 'plan') {
    const sets = D.plan.then ? D.plan.then.length + 1 : 1;
    tabs.push(planTab(sets > 1 ? 'Set-up 1 order' : 'Plan order', D.plan, D.volumes));
    (D.plan.then || []).forEach((later, k) => tabs.push(planTab('Set-up ' + (k + 2) + ' order', later, D.later_volumes[k])));
    tabs.push(featureTab('Stiffness features', stiff, (f) => P['stiffness.' + f.kind] || P.other, stiffRows, kindLegend));
  }
  if (D.view === 'classification') tabs.push(classificationTab());
  if (D.view === 'access') tabs.push(reachTab(), accessTab());
  if (D.view === 'operations') {
    tabs.push(operationsTab('Operations', D.operations));
    (D.operations.then || []).forEach((later, k) => tabs.push(operationsTab('Set-up ' + (k + 2), later)));
  }

  function show(tab) {
    if (mode && mode.leave) mode.leave();
    mode = tab; selected = null;
    for (const b of $('#tabs').children) b.classList.toggle('on', b.textContent === tab.name);
    tab.enter();
  }
  function goTo(id) { // a feature id from anywhere: the tab that lists it
    if (mode.go && mode.select && D.volumes.some((v) => v.id === id)) return mode.select(id);
    const t = tabs.find((t) => t.name !== 'Plan order' && ((t.name === 'Stiffness features' && stiff.some((f) => f.id === id)) || (t.name === 'Machining features' && mach.some((f) => f.id === id))));
    if (t && t !== mode) show(t);
    mode.select(id);
  }
  $('#tabs').replaceChildren(...tabs.map((t) => el('button', { onclick: () => show(t) }, t.name)));
  $('#search').addEventListener('input', () => mode.list());
  viewer.onPick = (s, face) => mode.pickFace(face, s);

  const bar = $('#toolbar');
  const toggle = (name, key, apply) => { const b = el('button', { class: state[key] ? 'on' : '', onclick: () => { state[key] = !state[key]; b.classList.toggle('on', state[key]); apply(); viewer.render(); } }, name); return b; };
  bar.append(
    el('button', { onclick: () => viewer.iso() }, 'Iso'),
    el('button', { onclick: () => viewer.look(D.up) }, 'Top'),
    toggle('Edges', 'edges', () => { part.edges.visible = state.edges; for (const p of viewer.pickables) p.edges.visible = state.edges; }),
    toggle('Part', 'part', () => { part.group.visible = state.part; }),
    toggle('X-ray', 'xray', () => part.opacity(state.xray ? 0.28 : 1)),
  );
  if (state.xray) part.opacity(0.28);

  const file = rec ? rec.part.file : D.plan ? D.plan.file : D.classification ? D.classification.part : D.access ? D.access.part : D.operations ? D.operations.part : D.title;
  const faces = D.part.faces.length, missing = D.part.faces.filter((f) => !f.triangles.length).length;
  $('#title').replaceChildren(D.title, el('small', null, faces + ' faces' + (missing ? ', ' + missing + ' not drawn' : '') + ' · up ' + vec(D.up)));
  document.title = 'Thinwall: ' + file.split('/').pop();
  if (!['classification', 'access', 'operations'].includes(D.view)) graph.draw($('#bottom'));
  else $('#bottom').hidden = true;
  // `#wall=R2`, `#step=5`, `#select=H1`, `#tab=Machining features`: a
  // page opened at a chosen view (links in documents, screenshots).
  const want = new Map(decodeURIComponent(location.hash.slice(1)).split('&').filter(Boolean).map((kv) => kv.split('=')));
  show(tabs.find((t) => t.name === want.get('tab')) || tabs[0]);
  viewer.iso();
  if (mode.setWall && want.has('wall')) mode.setWall(want.get('wall'));
  if (mode.go && want.has('step')) mode.go(+want.get('step') - 1);
  if (want.has('select')) goTo(want.get('select'));
})();
