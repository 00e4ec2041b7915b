// Robot in the loop: lists the evaluations with their tables (means with 95 % intervals over the
// cards), and watches a co-simulation (issue 19, docs/cosim.md) by polling
// GET /api/v1/cosim/{id}/view — people as they are now, the robot drawn apart from them (an orange
// body with its heading, its radius to scale), the path it has driven, its goal, and every contact
// with a person (bodies within 2 cm, the metrics' collision rule) marked where it began.
import { $, el, getJson, setStatus, setLive, showLegend, drawPlan, COLOURS } from './common.js';

const POLL_MS = 150;
const view = { id: null, world: null, frames: 0, paths: [], contacts: [], last: null, timer: null, base: null };

function sessionItem(s) {
  const what = s.card_id ? `card ${s.card_id}` : 'program';
  const li = el('li', { 'data-id': s.id, tabindex: '0' },
    el('b', {}, s.id), ` · ${s.status}${s.end_reason ? ` (${s.end_reason})` : ''} · ${what} · step ${s.step}`);
  li.addEventListener('click', () => { location.hash = s.id; });
  li.addEventListener('keydown', (e) => { if (e.key === 'Enter') location.hash = s.id; });
  return li;
}

async function listSessions() {
  try {
    const page = await getJson('/cosim');
    $('sessions').replaceChildren(...page.items.map(sessionItem));
    if (!page.items.length) $('sessions').append(el('li', { class: 'muted' }, 'No co-simulation yet: open one with POST /api/v1/cosim.'));
  } catch (e) {
    setStatus(`co-simulations: ${e.message}`);
  }
}

function watch(id) {
  clearTimeout(view.timer);
  Object.assign(view, { id, world: null, frames: 0, paths: [], contacts: [], last: null });
  $('view').dataset.ready = '0';
  for (const li of $('sessions').children) li.classList.toggle('current', li.dataset.id === id);
  poll();
}

async function poll() {
  const id = view.id;
  let v;
  try {
    v = await getJson(`/cosim/${encodeURIComponent(id)}/view?since=${view.frames}&world=${view.world ? 'false' : 'true'}`);
  } catch (e) {
    setStatus(`co-simulation ${id}: ${e.message}`);
    setLive(false);
    return;
  }
  if (id !== view.id) return;  // another session was chosen meanwhile
  if (v.world) view.world = v.world;
  v.robots.forEach((r, k) => {
    view.paths[k] = (view.paths[k] || []).concat(r.path);
    for (const c of r.contacts) view.contacts.push({ robot: r.name, ...c });
  });
  view.frames = v.frames;
  view.last = v;
  draw();
  show(v);
  const running = v.status !== 'ended';
  setLive(running);
  if (running) view.timer = setTimeout(poll, POLL_MS);
  else listSessions();  // the list shows it ended
}

function show(v) {
  $('session-info').textContent = `${v.id} · ${v.status}${v.end_reason ? ` (${v.end_reason})` : ''} · step ${v.step} · t = ${v.t.toFixed(2)} s · ${v.people.length} ${v.people.length === 1 ? 'person' : 'people'}`;
  $('robots').replaceChildren(...v.robots.flatMap((r) => [
    el('dt', {}, r.name),
    el('dd', { 'data-outcome': r.outcome }, `${r.outcome} · at (${r.pose.x.toFixed(2)}, ${r.pose.y.toFixed(2)})` +
      (r.goal ? ` · goal (${r.goal.x}, ${r.goal.y})` : '') + (r.visible ? '' : ' · invisible to people')),
  ]));
  $('contacts').replaceChildren(...view.contacts.map((c) =>
    el('li', {}, `${c.robot} and person ${c.person} at t = ${c.t.toFixed(2)} s, (${c.x.toFixed(2)}, ${c.y.toFixed(2)})`)));
  if (!view.contacts.length) $('contacts').append(el('li', { class: 'muted' }, 'none'));
  const report = v.report?.metrics?.robots;
  if (report) {
    $('report').classList.remove('muted');
    $('report').replaceChildren(...report.map((m) => el('p', {},
      el('b', {}, m.name), ` ${m.outcome} · path ${m.path_length.toFixed(2)} m · min distance ${m.minimum_distance_to_people.toFixed(2)} m · ` +
      `intimate ${m.intimate_space_intrusions.toFixed(1)} % · collisions ${m.collisions} · path efficiency ${m.path_efficiency.toFixed(2)}`)));
  }
}

function draw() {
  const canvas = $('view');
  const v = view.last;
  const t = drawPlan(canvas, view.world || {}, { entityLabels: false });
  const ctx = canvas.getContext('2d');
  const px = (x, y) => t.toPx([x, y]);
  // People, coloured by state.
  for (const p of v.people) {
    const [x, y] = px(p.x, p.y);
    ctx.beginPath();
    ctx.arc(x, y, Math.max(2.5, 0.25 * t.scale), 0, 2 * Math.PI);
    ctx.fillStyle = COLOURS.state[p.state] || COLOURS.state.walking;
    ctx.fill();
  }
  const ink = COLOURS.robot;
  v.robots.forEach((r, k) => {
    // The path driven so far.
    const path = view.paths[k] || [];
    ctx.strokeStyle = ink.path;
    ctx.lineWidth = 2;
    ctx.setLineDash([6, 4]);
    ctx.beginPath();
    path.forEach(([x, y], i) => { const [a, b] = px(x, y); i ? ctx.lineTo(a, b) : ctx.moveTo(a, b); });
    ctx.stroke();
    ctx.setLineDash([]);
    // The goal: a ring of the success radius with a cross.
    if (r.goal) {
      const [gx, gy] = px(r.goal.x, r.goal.y);
      const gr = Math.max(6, (r.goal.radius || 0.5) * t.scale);
      ctx.strokeStyle = ink.goal;
      ctx.lineWidth = 2;
      ctx.beginPath(); ctx.arc(gx, gy, gr, 0, 2 * Math.PI); ctx.stroke();
      ctx.beginPath(); ctx.moveTo(gx - 5, gy); ctx.lineTo(gx + 5, gy); ctx.moveTo(gx, gy - 5); ctx.lineTo(gx, gy + 5); ctx.stroke();
    }
    // The body: a square of the robot's radius turned by its yaw, with a heading wedge.
    const [cx, cy] = px(r.pose.x, r.pose.y);
    const s = Math.max(6, r.radius * t.scale);
    ctx.save();
    ctx.translate(cx, cy);
    ctx.rotate(-r.pose.yaw);
    ctx.fillStyle = ink.body;
    ctx.strokeStyle = ink.edge;
    ctx.lineWidth = 2;
    ctx.fillRect(-s, -s, 2 * s, 2 * s);
    ctx.strokeRect(-s, -s, 2 * s, 2 * s);
    ctx.beginPath(); ctx.moveTo(s * 1.6, 0); ctx.lineTo(s * 0.4, -s * 0.6); ctx.lineTo(s * 0.4, s * 0.6); ctx.closePath();
    ctx.fillStyle = ink.edge;
    ctx.fill();
    ctx.restore();
    ctx.fillStyle = ink.edge;
    ctx.font = 'bold 12px system-ui, sans-serif';
    ctx.fillText(r.name, cx + s + 4, cy - s - 2);
  });
  // Contacts: a red cross where each began.
  ctx.strokeStyle = COLOURS.robot.contact;
  ctx.lineWidth = 3;
  for (const c of view.contacts) {
    const [x, y] = px(c.x, c.y);
    ctx.beginPath(); ctx.moveTo(x - 7, y - 7); ctx.lineTo(x + 7, y + 7); ctx.moveTo(x + 7, y - 7); ctx.lineTo(x - 7, y + 7); ctx.stroke();
  }
  canvas.dataset.contacts = String(view.contacts.length);
  canvas.dataset.ready = '1';
}

// ---------------------------------------------------------------- evaluations

// The columns of an evaluation's table: metric, heading, digits (means with their 95 % interval).
const EVAL_COLUMNS = [
  ['success', 'success', 2], ['collision', 'collision', 2], ['time_to_reach_goal', 'time to goal (s)', 1],
  ['path_length', 'path (m)', 1], ['path_efficiency', 'path efficiency', 2],
  ['minimum_distance_to_people', 'min distance (m)', 2], ['intimate_space_intrusions', 'intimate (%)', 1],
  ['group_personal_space_intrusions', 'group personal (%)', 1], ['social_work', 'social work', 1],
];

function figure(f, digits) {
  if (!f || typeof f.mean !== 'number') return 'n/a';
  const ci = Array.isArray(f.ci95) ? ` [${f.ci95[0].toFixed(digits)}, ${f.ci95[1].toFixed(digits)}]` : '';
  return f.mean.toFixed(digits) + ci;
}

async function listEvaluations() {
  try {
    const page = await getJson('/evaluations?page_size=20');
    $('evaluations').replaceChildren(...page.items.map((e) => {
      const what = `${e.request.cards.length} card${e.request.cards.length === 1 ? '' : 's'} × ${e.request.seeds.length} seed${e.request.seeds.length === 1 ? '' : 's'}`;
      const who = e.request.client || (e.request.planners || []).join(', ');
      const li = el('li', { 'data-id': e.id, tabindex: '0' }, el('b', {}, e.status), ` · ${what} · ${who}`);
      li.addEventListener('click', () => showEvaluation(e.id));
      li.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') showEvaluation(e.id); });
      return li;
    }));
    if (!page.items.length) $('evaluations').append(el('li', { class: 'muted' }, 'None yet.'));
  } catch (e) {
    setStatus(`evaluations: ${e.message}`);
  }
}

async function showEvaluation(id) {
  for (const li of $('evaluations').children) li.classList.toggle('current', li.dataset.id === id);
  const e = await getJson(`/evaluations/${encodeURIComponent(id)}`);
  $('evaluation').hidden = false;
  $('evaluation-title').textContent = `Evaluation ${e.id} · ${e.status}` + (e.current ? ` · episode ${e.current.episode} of ${e.current.episodes}` : '');
  const table = e.result?.table;
  $('evaluation-interval').textContent = table ? `Means over the cards, ${table.interval}.` : (e.message || e.error?.detail || '');
  $('evaluation-table').tHead.replaceChildren(el('tr', {}, el('th', {}, 'planner'), el('th', {}, 'episodes'),
    ...EVAL_COLUMNS.map(([, head]) => el('th', {}, head))));
  $('evaluation-table').tBodies[0].replaceChildren(...(table?.planners || []).map((p) =>
    el('tr', { 'data-planner': p.planner }, el('td', {}, p.planner), el('td', {}, String(p.episodes)),
      ...EVAL_COLUMNS.map(([name, , digits]) => el('td', {}, figure(p.metrics[name], digits))))));
  $('evaluation').dataset.ready = '1';
}

// For tests: how many points of robot 0's path the page holds (fetched in pieces, each frame once).
window.__cosimPathLength = () => (view.paths[0] || []).length;

showLegend($('legend'), [
  ['robot', COLOURS.robot.body], ['robot path', COLOURS.robot.path], ['goal', COLOURS.robot.goal],
  ['contact with a person', COLOURS.robot.contact], ...Object.entries(COLOURS.state).slice(0, 5),
]);
window.addEventListener('hashchange', () => { if (location.hash.length > 1) watch(location.hash.slice(1)); });
await Promise.all([listSessions(), listEvaluations()]);
setInterval(listSessions, 3000);
setInterval(listEvaluations, 5000);
if (location.hash.length > 1) watch(location.hash.slice(1));
else setStatus('Choose a co-simulation.');
