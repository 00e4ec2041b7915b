// The page kit every socsim page imports: the API helpers (JSON fetch that turns
// application/problem+json into a readable error, jobs with progress), the DOM helpers, the one
// header and navigation, the one colour table, and the one plan drawer with the converters from
// the server's house shapes. Plain ES module, no build step.

export const api = '/api/v1';
export const $ = (id) => document.getElementById(id);

export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v; else if (k.startsWith('on')) e.addEventListener(k.slice(2), v); else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// ---------------------------------------------------------------- API

// A problem (RFC 9457, as the server's error table writes it) as one readable text: the title, the
// detail, then one line per field error with its JSON pointer or query parameter.
export function problemText(p, fallback = 'error') {
  if (!p || typeof p !== 'object') return fallback;
  const head = [p.title, p.detail].filter(Boolean).join(': ') || fallback;
  const fields = (p.errors || []).map((e) => {
    const where = [e.pointer, e.parameter && `?${e.parameter}`, e.line > 0 && `line ${e.line}:${e.column}`].filter(Boolean).join(' ');
    return `  ${where ? where + ': ' : ''}${e.message}`;
  });
  return [head, ...fields].join('\n');
}

// Fetches `api + path`; a non-2xx answer throws an Error whose message is problemText() of the body.
export async function requestJson(method, path, body) {
  const r = await fetch(api + path, {
    method, headers: body === undefined ? {} : { 'Content-Type': 'application/json' },
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  const text = await r.text();
  let json = {};
  try { json = text ? JSON.parse(text) : {}; } catch { if (r.ok) throw new Error(`${path}: the answer is not JSON`); }
  if (!r.ok) {
    const e = new Error(problemText(json, `HTTP ${r.status} ${r.statusText}`));
    e.status = r.status;
    e.problem = json;
    throw e;
  }
  return json;
}
export const getJson = (path) => requestJson('GET', path);
export const postJson = (path, body) => requestJson('POST', path, body);

// "running: simulating 12 of 30 s 40 %"
export const jobText = (job) => `${job.status}: ${job.message || ''} ${Math.round((job.progress || 0) * 100)} %`;

// Polls a job until it ends. `bar` (a <progress>) is shown while it runs; `onUpdate(job)` sees every
// poll. Returns the succeeded job; a failed or cancelled job throws with the job's problem.
export async function waitForJob(id, { bar = null, onUpdate = null, interval = 250 } = {}) {
  if (bar) { bar.value = 0; bar.hidden = false; }
  try {
    for (;;) {
      const job = await getJson(`/jobs/${encodeURIComponent(id)}`);
      if (bar) bar.value = job.progress || 0;
      onUpdate?.(job);
      if (job.status === 'succeeded') return job;
      if (job.status === 'failed' || job.status === 'cancelled') throw new Error(problemText(job.error, `job ${job.status}`));
      await sleep(interval);
    }
  } finally {
    if (bar) bar.hidden = true;
  }
}

// ---------------------------------------------------------------- page frame

const PAGES = [
  ['./', 'Text to scenario'],
  ['catalogue.html', 'Scenario cards'],
  ['household.html', 'Households'],
  ['navbench.html', 'Navigation benchmark'],
  ['cosim.html', 'Robot in the loop'],
];

// The one header: name, navigation with the current page marked, the page's status line, the
// server's version and (pages with a live feed only) the live badge.
function mountHeader() {
  const file = location.pathname.split('/').pop() || 'index.html';
  const current = (href) => (href === './' ? 'index.html' : href) === file;
  const nav = el('nav', { 'aria-label': 'Pages' }, ...PAGES.map(([href, text]) =>
    el('a', current(href) ? { href, 'aria-current': 'page' } : { href }, text)));
  document.body.prepend(el('header', {},
    el('h1', {}, el('a', { href: './' }, 'socsim')), nav,
    el('span', { id: 'status', class: 'muted', 'aria-live': 'polite' }),
    el('span', { id: 'server-info', class: 'muted' }, 'connecting…'),
    el('span', { id: 'live', class: 'badge off', title: 'live events over WebSocket', hidden: '' }, 'live')));
}
mountHeader();

// GET /api/v1/info, asked once per page; the header shows the version and the generators.
export const serverInfo = getJson('/info');
serverInfo.then((info) => {
  const gens = info.generators.filter((g) => g.available).map((g) => g.name).join(', ');
  $('server-info').textContent = `v${info.version} · generators: ${gens}`;
}, () => { $('server-info').textContent = 'server not reachable'; });

export function setStatus(text) { $('status').textContent = text; }

// The live badge: hidden until a page says it follows a feed, then green while connected.
export function setLive(on) {
  const badge = $('live');
  badge.hidden = false;
  badge.className = on ? 'badge on' : 'badge off';
}

export function toast(text) {
  let t = $('toast');
  if (!t) { t = el('div', { id: 'toast', role: 'status', hidden: '' }); document.body.append(t); }
  t.textContent = text;
  t.hidden = false;
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => { t.hidden = true; }, 3000);
}

// Swatch-and-name items of a legend, from [name, colour] pairs.
export function showLegend(container, entries) {
  container.replaceChildren(...entries.map(([name, c]) => el('span', {}, el('i', { class: 'swatch', style: `background:${c}` }), name)));
}

// ---------------------------------------------------------------- colours

export const COLOURS = {
  // Zone and room types (snake_case; house rooms are converted to it on arrival).
  room: {
    corridor: '#e8e4da', lobby: '#dfe9f5', reception: '#dfe9f5', waiting_room: '#e4f1e4', waiting_area: '#e4f1e4',
    patient_room: '#f5e6e6', office: '#eef0e0', open_office: '#eef0e0', meeting_room: '#efe4f3', kitchen: '#f8efd9',
    living_room: '#e6eef6', bedroom: '#f2e8f1', bathroom: '#dff3f3', canteen: '#f8efd9', storage: '#e9e9e9',
  },
  roomOther: '#f1f3f5',
  // Segmentation regions (ROIs), drawn dashed.
  region: { queue_lane: '#d9480f', seating_area: '#2b8a3e', waiting_zone: '#1971c2', corridor: '#868e96', entrance: '#5f3dc4' },
  regionOther: '#495057',
  // Agent states of a simulation.
  state: {
    walking: '#1c7ed6', standing: '#868e96', queuing: '#e8590c', sitting: '#2b8a3e', interacting: '#ae3ec9',
    evacuating: '#e03131', waiting: '#f59f00', running: '#c2255c', exited: '#ced4da',
  },
  // Agent roles of a simulation, by the role's index.
  role: ['#1c7ed6', '#e8590c', '#2b8a3e', '#ae3ec9', '#e03131', '#0c8599', '#f59f00', '#5f3dc4', '#495057', '#c2255c'],
  // Groups of household activities (schedule timelines).
  activity: { sleep: '#5c6bc0', away: '#bdbdbd', meal: '#f4a261', hygiene: '#4fc3f7', chores: '#81c784', work: '#e57373', leisure: '#ba68c8' },
  // The plan's own ink.
  plan: { wall: '#212529', door: '#f08c00', entity: '#343a40', label: '#212529', entityLabel: '#495057', furniture: '#d9d2c5', furnitureEdge: '#8d8577', window: '#4dabf7' },
  // Marks drawn over a plan: the navigation target, receptacles visited, the agent's path, the time cursor.
  mark: { target: '#e03131', visited: '#2b8a3e', path: '#1c7ed6', agent: '#0b3d91', free: '#c8c8c8', now: '#d6336c' },
  // A co-simulated robot: its body, its path, its goal, a contact with a person.
  robot: { body: '#f08c00', edge: '#7a4100', path: '#f08c00', goal: '#2b8a3e', contact: '#e03131' },
};

// ---------------------------------------------------------------- plan drawer
//
// One plan shape, the JSON form of world.yaml (schemas/world.schema.json), metres, y up:
//   zones [{name, type, polygon: [[x, y]…], label?}], walls [{start, end}], doors [{name, pose: [x, y], width, along?}],
//   segmentation [{name, kind, polygon}], entities [{name, type, pose: [x, y, yaw?], size?: [w, d]}].
// Extras the houses need: windows [{pose, width, along}] (drawn as a light line across the wall),
// a zone's `label` (else its name is shown), a door's `along` (unit vector
// of the opening; else taken from the nearest wall or zone edge), an entity's `size` (drawn as a
// rectangle turned by yaw, radians, instead of a point).

// House coordinates (x, z on the floor, z towards the viewer's bottom) to plan coordinates.
export const fromHouse = (x, z) => [x, -z];

const roomType = (t) => String(t).replace(/([a-z0-9])([A-Z])/g, '$1_$2').toLowerCase();  // LivingRoom → living_room

// The one house-plan shape (household::house_plan_json): GET /api/v1/households/{id} → .house and
// GET /api/v1/navbench/{job}/episodes/{n} → .house (which adds each room's floor as a receptacle,
// "synthetic": true, drawn as a point, and the map's grid, drawn by the page).
// rooms [{id, type, floor: [{x, z}]}], walls [{a, b}], doors [{center, direction, width}], windows
// (same form), receptacles [{id, type, position, size: {x, z}, yaw (degrees)}].
export function planFromHousehold(house) {
  return {
    name: house.id,
    zones: house.rooms.map((r) => ({
      name: r.id, type: roomType(r.type), label: r.type + (r.id ? ` ${r.id.replace(/^room\|/, '#')}` : ''),
      polygon: r.floor.map((p) => fromHouse(p.x, p.z)),
    })),
    walls: house.walls.map((w) => ({ start: fromHouse(w.a.x, w.a.z), end: fromHouse(w.b.x, w.b.z) })),
    doors: house.doors.filter((d) => d.center).map((d) => ({
      name: d.id, pose: fromHouse(d.center.x, d.center.z), width: d.width || 0.9, along: fromHouse(d.direction.x, d.direction.z),
    })),
    windows: (house.windows || []).map((w) => ({
      pose: fromHouse(w.center.x, w.center.z), width: w.width, along: fromHouse(w.direction.x, w.direction.z),
    })),
    entities: house.receptacles.map((r) => ({
      name: r.id, type: r.type, pose: [...fromHouse(r.position.x, r.position.z), (r.yaw || 0) * Math.PI / 180],
      size: r.synthetic ? undefined : [r.size.x, r.size.z],
    })),
  };
}

// A transform {scale, ox, oy, toPx} mapping plan metres to canvas pixels, fitting the plan's bounds.
export function planTransform(plan, width, height, margin = 20) {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  const grow = ([x, y]) => { minX = Math.min(minX, x); minY = Math.min(minY, y); maxX = Math.max(maxX, x); maxY = Math.max(maxY, y); };
  for (const z of plan.zones || []) z.polygon.forEach(grow);
  for (const w of plan.walls || []) { grow(w.start); grow(w.end); }
  let scale = 1, ox = 0, oy = 0;
  if (isFinite(minX)) {
    scale = Math.min((width - 2 * margin) / Math.max(maxX - minX, 1e-6), (height - 2 * margin) / Math.max(maxY - minY, 1e-6));
    ox = margin - minX * scale + (width - 2 * margin - (maxX - minX) * scale) / 2;
    oy = height - margin + minY * scale - (height - 2 * margin - (maxY - minY) * scale) / 2;
  }
  return { scale, ox, oy, toPx: ([x, y]) => [ox + x * scale, oy - y * scale] };
}

// The direction of the wall or zone edge nearest to a door, for doors that do not say it.
function nearestEdgeDirection(plan, at) {
  let best = Infinity, dir = null;
  const consider = (a, b) => {
    const dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    if (!len2) return;
    const u = Math.min(1, Math.max(0, ((at[0] - a[0]) * dx + (at[1] - a[1]) * dy) / len2));
    const ex = a[0] + u * dx - at[0], ey = a[1] + u * dy - at[1], d = ex * ex + ey * ey;
    if (d < best) { best = d; const len = Math.sqrt(len2); dir = [dx / len, dy / len]; }
  };
  for (const z of plan.zones || []) z.polygon.forEach((p, i) => consider(p, z.polygon[(i + 1) % z.polygon.length]));
  for (const w of plan.walls || []) consider(w.start, w.end);
  return dir;
}

function tracePolygon(ctx, t, polygon) {
  ctx.beginPath();
  polygon.forEach((p, i) => { const [x, y] = t.toPx(p); i ? ctx.lineTo(x, y) : ctx.moveTo(x, y); });
  ctx.closePath();
}

// Draws a plan on a canvas and returns its transform, for the page to draw people or paths over.
// opts: labels (zone and entity names; default true), entityLabels (default true), entityFill(entity)
// (a colour, or undefined for the default), underlay(ctx, transform) (drawn over the floors, under the walls).
export function drawPlan(canvas, plan, opts = {}) {
  const ctx = canvas.getContext('2d');
  const t = planTransform(plan, canvas.width, canvas.height);
  const ink = COLOURS.plan;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.font = '12px system-ui, sans-serif';
  for (const z of plan.zones || []) {
    tracePolygon(ctx, t, z.polygon);
    ctx.fillStyle = COLOURS.room[z.type] || COLOURS.roomOther;
    ctx.fill();
  }
  opts.underlay?.(ctx, t);
  ctx.lineWidth = 1.2;
  ctx.setLineDash([4, 3]);
  for (const r of plan.segmentation || []) {
    tracePolygon(ctx, t, r.polygon);
    ctx.strokeStyle = COLOURS.region[r.kind] || COLOURS.regionOther;
    ctx.stroke();
  }
  ctx.setLineDash([]);
  ctx.strokeStyle = ink.wall;
  ctx.lineWidth = Math.min(5, Math.max(2.5, 0.1 * t.scale));  // a wall stays a line on a large plan
  ctx.lineCap = 'round';
  for (const w of plan.walls || []) {
    const [ax, ay] = t.toPx(w.start), [bx, by] = t.toPx(w.end);
    ctx.beginPath(); ctx.moveTo(ax, ay); ctx.lineTo(bx, by); ctx.stroke();
  }
  ctx.strokeStyle = ink.window;  // a window: a light line over the wall, a third of its thickness
  ctx.lineWidth = Math.max(1.5, 0.035 * t.scale);
  for (const w of plan.windows || []) {
    const [cx, cy] = t.toPx(w.pose);
    const half = w.width * t.scale / 2;
    ctx.beginPath();
    ctx.moveTo(cx - w.along[0] * half, cy + w.along[1] * half);
    ctx.lineTo(cx + w.along[0] * half, cy - w.along[1] * half);
    ctx.stroke();
  }
  const doors = plan.doors || [];
  const infer = doors.length * ((plan.walls || []).length + 8 * (plan.zones || []).length) < 2e6;  // no quadratic stall on huge worlds
  ctx.strokeStyle = ink.door;
  ctx.fillStyle = ink.door;
  ctx.lineWidth = Math.max(3, 0.1 * t.scale);
  for (const d of doors) {
    const [cx, cy] = t.toPx(d.pose);
    const along = d.along || (infer ? nearestEdgeDirection(plan, d.pose) : null);
    if (!along) { ctx.beginPath(); ctx.arc(cx, cy, Math.max(3, 0.12 * t.scale), 0, 2 * Math.PI); ctx.fill(); continue; }
    const half = (d.width || 0.9) * t.scale / 2;  // pixels, along the opening (y flips on screen)
    ctx.beginPath();
    ctx.moveTo(cx - along[0] * half, cy + along[1] * half);
    ctx.lineTo(cx + along[0] * half, cy - along[1] * half);
    ctx.stroke();
  }
  ctx.lineCap = 'butt';
  for (const e of plan.entities || []) {
    const [px, py] = t.toPx(e.pose);
    const fill = opts.entityFill?.(e);
    if (e.size) {
      const w = e.size[0] * t.scale, h = e.size[1] * t.scale;
      ctx.save();
      ctx.translate(px, py);
      ctx.rotate(-(e.pose[2] || 0));
      ctx.fillStyle = fill || ink.furniture;
      ctx.fillRect(-w / 2, -h / 2, w, h);
      ctx.strokeStyle = ink.furnitureEdge;
      ctx.lineWidth = 1;
      ctx.strokeRect(-w / 2, -h / 2, w, h);
      ctx.restore();
    } else {
      ctx.fillStyle = fill || ink.entity;
      ctx.fillRect(px - 3, py - 3, 6, 6);
    }
    if (opts.labels !== false && opts.entityLabels !== false) { ctx.fillStyle = ink.entityLabel; ctx.fillText(e.name, px + 5, py - 4); }
  }
  if (opts.labels !== false) {
    ctx.fillStyle = ink.label;
    for (const z of plan.zones || []) {
      const cx = z.polygon.reduce((s, p) => s + p[0], 0) / z.polygon.length;
      const cy = z.polygon.reduce((s, p) => s + p[1], 0) / z.polygon.length;
      const [px, py] = t.toPx([cx, cy]);
      const label = z.label ?? z.name;
      ctx.fillText(label, px - ctx.measureText(label).width / 2, py);
    }
  }
  return t;
}
