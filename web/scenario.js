// socsim text-to-scenario page (the landing page, /): prompt → what was understood (POST
// /api/v1/scenarios/interpret as you type) → job (progress) → scenario card → a live session of the
// card's recorded trajectories streamed over WebSocket, drawn over the world on a Canvas 2D with
// interpolation between frames and trails; play/pause/speed/seek go over the socket. The stage
// says how many people it shows (data-people, data-roles). Plain ES module, no build step.
import { $, api, el, getJson, postJson, jobText, waitForJob, toast, serverInfo, showLegend, COLOURS, drawPlan } from './common.js';
import { clearIntent, showIntent, showIntentProblem } from './intent.js';

const STATE_COLOURS = COLOURS.state;
const ROLE_PALETTE = COLOURS.role;
const TRAIL = 24;  // frames of history drawn per agent
const MAX_TRAILED = 3000;  // above this many people, no trails or heading ticks (keeps 10k agents smooth)

const view = {
  card: null, world: null, base: null, transform: null, ws: null, wsBase: null, session: null,
  prev: null, curr: null, prevIndex: new Map(), currIndex: new Map(), states: Object.keys(STATE_COLOURS), currAt: 0, interval: 0.1, t: 0, paused: false, trails: new Map(),
  roles: [], duration: 60, frames: 0, seeking: false,
};

// ---------------------------------------------------------------- prompt → what was understood
// Only the latest request may paint the panel: answers that arrive after a newer one was sent
// (typing on, a card opened) are dropped.
let interpretSeq = 0;
let interpretTimer = 0;

async function interpret(prompt, source) {
  const seq = ++interpretSeq;
  try {
    const intent = await postJson('/scenarios/interpret', { prompt });
    if (seq === interpretSeq) showIntent(intent, source);
  } catch (err) {
    if (seq === interpretSeq) showIntentProblem(err.message, source);
  }
}

function interpretTyped(delay = 300) {
  clearTimeout(interpretTimer);
  if (!$('prompt').value.trim()) {
    ++interpretSeq;
    clearIntent('Type a prompt to see how it is read.');
    return;
  }
  interpretTimer = setTimeout(() => interpret($('prompt').value, 'From the prompt as you type:'), delay);
}

// A card's own interpretation when it stores one (`intent`; offline cards also carry it in their
// provenance), else its prompt read now.
function showCardIntent(card) {
  clearTimeout(interpretTimer);
  const stored = [card.intent, card.provenance?.program?.scenario_intent]
    .find((i) => i && typeof i === 'object' && typeof i.prompt === 'string' && Array.isArray(i.groups));
  if (stored) {
    ++interpretSeq;
    showIntent(stored, `Stored with card ${card.id}:`);
  } else if (card.prompt) {
    interpret(card.prompt, `Card ${card.id} (its prompt, read now):`);
  }
}

// ---------------------------------------------------------------- prompt → job → card
async function submitPrompt(e) {
  e.preventDefault();
  $('error').textContent = '';
  const body = { prompt: $('prompt').value.trim(), seed: Number($('seed').value || 0), generator: $('generator').value,
    duration_s: Number($('duration').value || 60) };
  if ($('agents').value) body.agents = Number($('agents').value);
  const source = $('world-source').value;
  if ($('world-id').value) body.world_id = $('world-id').value;
  else if (source === 'scene_graph') {
    try { body.scene_graph = JSON.parse($('scene-graph').value); } catch (err) { $('error').textContent = `scene graph: ${err.message}`; return; }
  } else if (source !== 'prompt') body.domain = source;
  $('generate').disabled = true;
  try {
    const job = await postJson('/scenarios', body);
    const done = await waitForJob(job.id, { bar: $('progress'), onUpdate: (j) => { $('job-status').textContent = jobText(j); } });
    await openCard(done.result.card_id);
    loadRecent();
  } catch (err) {
    $('error').textContent = err.message;
    $('job-status').textContent = '';
  } finally {
    $('generate').disabled = false;
  }
}

// ---------------------------------------------------------------- card → session → stream
async function openCard(id) {
  stopStream();
  const card = await getJson(`/cards/${encodeURIComponent(id)}`);
  view.card = card;
  history.replaceState(null, '', `#card=${id}`);
  $('card-title').textContent = card.title;
  $('card-description').textContent = `${card.description} Seed ${card.seed}, ${card.generator.name}${card.generator.model ? ' (' + card.generator.model + ')' : ''}.`;
  $('catalogue-link').href = `catalogue.html#card=${id}`;
  $('share').href = `./#card=${id}`;
  $('csv').href = `${api}/cards/${id}/export?format=csv`;
  view.world = card.world;
  view.duration = card.trajectory_log?.duration_s || 60;
  $('seek').max = String(view.duration);
  prepareStage();
  showMetrics(card.metrics);
  showCardIntent(card);
  if (!card.trajectory_log) { $('stream-status').textContent = 'this card has no trajectory log'; return; }
  const session = await postJson('/simulations', { card_id: id, speed: Number($('speed').value) });
  connect(session);
}

function wsUrl(session) {
  const u = session.websocket_url || session.ws_url || `/ws/simulations/${session.id}`;
  if (/^wss?:/.test(u)) return u;
  return view.wsBase.replace(/\/ws$/, '') + u;
}

function connect(session) {
  view.session = session;
  // Compact binary frames (schemas/simulation_binary_frame.md) decode straight into typed arrays;
  // control and status messages stay JSON text.
  const url = wsUrl(session);
  const ws = new WebSocket(url + (url.includes('?') ? '&' : '?') + 'format=binary');
  ws.binaryType = 'arraybuffer';
  view.ws = ws;
  $('stream-status').textContent = 'connecting…';
  ws.onopen = () => { $('stream-status').textContent = 'streaming'; $('play').disabled = false; };
  ws.onclose = () => { if (view.ws === ws) { $('stream-status').textContent = 'stream ended'; $('play').disabled = true; } };
  ws.onmessage = (m) => {
    if (typeof m.data !== 'string') { onFrame(decodeBinaryFrame(m.data)); return; }
    const msg = JSON.parse(m.data);
    if (msg.type === 'hello') {
      view.roles = msg.roles || [];
      view.states = msg.states || Object.keys(STATE_COLOURS);
      if (msg.frame_hz) view.interval = 1 / msg.frame_hz;
      if (msg.duration_s) { view.duration = msg.duration_s; $('seek').max = String(msg.duration_s); }
      $('seek').disabled = !msg.seekable;
      legend();
    } else if (msg.type === 'frame') {
      onFrame(fromJsonFrame(msg));
    } else if (msg.type === 'status') {
      view.paused = !!msg.paused;
      $('stage').dataset.paused = view.paused ? '1' : '0';  // the server's word: no frames follow a pause
      $('play').textContent = view.paused ? 'Play' : 'Pause';
    } else if (msg.type === 'end') {
      $('stream-status').textContent = `ended (${msg.reason || 'done'})`;
    }
  };
}

function stopStream() {
  if (view.ws) { const ws = view.ws; view.ws = null; ws.close(); }
  $('stage').dataset.people = '0';
  delete $('stage').dataset.roles;
  view.prev = null; view.curr = null; view.prevIndex = new Map(); view.currIndex = new Map(); view.trails.clear();
}

function send(action, value) {
  if (view.ws && view.ws.readyState === WebSocket.OPEN) view.ws.send(JSON.stringify(value === undefined ? { action } : { action, value }));
}

// A frame as typed arrays: n agents with id, x, y, yaw, state index and role index.
function makeFrame(n, t) {
  return { t, n, id: new Uint32Array(n), x: new Float32Array(n), y: new Float32Array(n), yaw: new Float32Array(n),
    state: new Uint8Array(n), role: new Uint8Array(n) };
}

// SSF1: 24-byte header (magic, u16 header size, u16 record size, u32 seq, f64 t, u32 count), then
// per agent u32 id, f32 x y yaw vx vy, i32 group, u8 state, u8 role, u16 target (little-endian).
function decodeBinaryFrame(buffer) {
  const v = new DataView(buffer);
  const header = v.getUint16(4, true), record = v.getUint16(6, true);
  const n = v.getUint32(20, true);
  const f = makeFrame(n, v.getFloat64(12, true));
  for (let i = 0, at = header; i < n; i++, at += record) {
    f.id[i] = v.getUint32(at, true);
    f.x[i] = v.getFloat32(at + 4, true);
    f.y[i] = v.getFloat32(at + 8, true);
    f.yaw[i] = v.getFloat32(at + 12, true);
    f.state[i] = v.getUint8(at + 28);
    f.role[i] = v.getUint8(at + 29);
  }
  return f;
}

function fromJsonFrame(msg) {
  const f = makeFrame(msg.agents.length, msg.t);
  msg.agents.forEach((a, i) => {
    f.id[i] = a.id; f.x[i] = a.x; f.y[i] = a.y; f.yaw[i] = a.yaw;
    f.state[i] = Math.max(0, view.states.indexOf(a.state)); f.role[i] = Math.max(0, view.roles.indexOf(a.role));
  });
  return f;
}

function onFrame(f) {
  if (f.t < view.t - 1e-6) { view.trails.clear(); view.curr = null; view.currIndex = new Map(); }  // a seek backwards
  view.prev = view.curr;
  view.prevIndex = view.currIndex;
  view.curr = f;
  view.currIndex = new Map();
  const keepTrails = f.n <= MAX_TRAILED;
  for (let i = 0; i < f.n; i++) {
    view.currIndex.set(f.id[i], i);
    if (!keepTrails) continue;
    let trail = view.trails.get(f.id[i]);
    if (!trail) { trail = []; view.trails.set(f.id[i], trail); }
    trail.push(f.x[i], f.y[i]);
    if (trail.length > 2 * TRAIL) trail.splice(0, 2);
  }
  if (!keepTrails) view.trails.clear();
  for (const id of view.trails.keys()) if (!view.currIndex.has(id)) view.trails.delete(id);
  view.currAt = performance.now();
  view.t = f.t;
  view.frames += 1;
  if (!view.seeking) $('seek').value = String(f.t);
  $('clock').textContent = `${f.t.toFixed(1)} s · ${f.n} people`;
  const byRole = {};
  for (let i = 0; i < f.n; i++) { const r = view.roles[f.role[i]] ?? String(f.role[i]); byRole[r] = (byRole[r] || 0) + 1; }
  $('stage').dataset.roles = JSON.stringify(byRole);
  liveCounts();
}

// ---------------------------------------------------------------- drawing
function prepareStage() {
  const stage = $('stage');
  view.base = document.createElement('canvas');
  view.base.width = stage.width;
  view.base.height = stage.height;
  // Zone names only: entity labels would hide the people standing at them.
  view.transform = drawPlan(view.base, view.world || {}, { entityLabels: false });
}

function colourAt(f, i) {
  if ($('colour-by').value === 'role') return ROLE_PALETTE[f.role[i] % ROLE_PALETTE.length];
  return STATE_COLOURS[view.states[f.state[i]]] || '#343a40';
}

function legend() {
  const byRole = $('colour-by').value === 'role';
  const items = byRole ? view.roles.map((r, i) => [r, ROLE_PALETTE[i % ROLE_PALETTE.length]]) : Object.entries(STATE_COLOURS);
  showLegend($('legend'), items);
}

function draw() {
  requestAnimationFrame(draw);
  const stage = $('stage');
  const ctx = stage.getContext('2d');
  if (!view.base) return;
  ctx.clearRect(0, 0, stage.width, stage.height);
  ctx.drawImage(view.base, 0, 0);
  const t = view.transform;
  const speed = Number($('speed').value) || 1;
  const alpha = view.paused ? 1 : Math.min(1, (performance.now() - view.currAt) / (1000 * view.interval / speed));
  const px = (x) => t.ox + x * t.scale;
  const py = (y) => t.oy - y * t.scale;
  const f = view.curr;
  if (!f) return;
  if ($('trails').checked) {
    ctx.lineWidth = 1;
    for (const [id, trail] of view.trails) {
      if (trail.length < 4) continue;
      const i = view.currIndex.get(id);
      ctx.strokeStyle = (i === undefined ? '#adb5bd' : colourAt(f, i)) + '66';
      ctx.beginPath();
      ctx.moveTo(px(trail[0]), py(trail[1]));
      for (let k = 2; k < trail.length; k += 2) ctx.lineTo(px(trail[k]), py(trail[k + 1]));
      ctx.stroke();
    }
  }
  // Bodies batched by colour: one path per colour, not one per agent.
  const r = Math.max(1.5, 0.25 * t.scale);
  const byColour = new Map();
  const p = view.prev, pi = view.prevIndex;
  const headings = f.n <= MAX_TRAILED;
  for (let i = 0; i < f.n; i++) {
    const j = p ? pi.get(f.id[i]) : undefined;
    const x = j === undefined ? f.x[i] : p.x[j] + (f.x[i] - p.x[j]) * alpha;
    const y = j === undefined ? f.y[i] : p.y[j] + (f.y[i] - p.y[j]) * alpha;
    const c = colourAt(f, i);
    let list = byColour.get(c);
    if (!list) { list = []; byColour.set(c, list); }
    list.push(px(x), py(y), f.yaw[i]);
  }
  stage.dataset.people = String(f.n);  // bodies on the canvas now
  for (const [c, list] of byColour) {
    ctx.fillStyle = c;
    ctx.beginPath();
    for (let k = 0; k < list.length; k += 3) { ctx.moveTo(list[k] + r, list[k + 1]); ctx.arc(list[k], list[k + 1], r, 0, 2 * Math.PI); }
    ctx.fill();
    if (!headings) continue;
    ctx.strokeStyle = '#212529';
    ctx.beginPath();
    for (let k = 0; k < list.length; k += 3) {
      ctx.moveTo(list[k], list[k + 1]);
      ctx.lineTo(list[k] + Math.cos(list[k + 2]) * r * 1.6, list[k + 1] - Math.sin(list[k + 2]) * r * 1.6);
    }
    ctx.stroke();
  }
}

// ---------------------------------------------------------------- metrics
function showMetrics(m) {
  if (!m || !m.summary) { $('metrics').textContent = '—'; return; }
  const cols = ['agents', 'goal_reached', 'mean_time_to_reach_goal', 'mean_path_length', 'minimum_distance_to_people',
    'mean_intimate_space_intrusions', 'mean_personal_space_intrusions', 'mean_time_not_moving', 'collisions'];
  const fmt = (v) => (v === null || v === undefined ? '—' : typeof v === 'number' && !Number.isInteger(v) ? v.toFixed(2) : String(v));
  const rows = [['all', m.summary], ...Object.entries(m.by_role || {})];
  const table = el('table', { class: 'data' },
    el('tr', {}, el('th', {}, 'who'), ...cols.map((c) => el('th', {}, c.replace(/_/g, ' ')))),
    ...rows.map(([who, s]) => el('tr', {}, el('td', {}, who), ...cols.map((c) => el('td', {}, fmt(s[c]))))));
  $('metrics').replaceChildren(
    el('p', {}, `${fmt(m.duration)} s simulated, mean speed ${fmt(m.avg_pedestrian_velocity)} m/s.`),
    table, el('p', { id: 'live-counts', class: 'muted' }, ''));
}

function liveCounts() {
  const counts = {};
  const f = view.curr;
  for (let i = 0; i < f.n; i++) { const st = view.states[f.state[i]]; counts[st] = (counts[st] || 0) + 1; }
  const node = $('live-counts');
  if (node) node.textContent = 'now: ' + Object.entries(counts).map(([s, n]) => `${n} ${s}`).join(', ');
}

// ---------------------------------------------------------------- lists
async function loadRecent() {
  try {
    const page = await getJson('/cards?tag=scenario&page_size=10');
    $('recent').replaceChildren(...page.items.map((c) => el('li', { 'data-id': c.id, onclick: () => openCard(c.id).catch((e) => toast(e.message)) },
      el('span', { class: 'title' }, c.title), ' ', el('span', { class: 'muted' }, c.domain || ''))));
  } catch (e) {
    toast(`Could not list cards: ${e.message}`);
  }
}

async function loadWorlds() {
  try {
    const page = await getJson('/worlds?page_size=50');
    for (const w of page.items) $('world-id').append(el('option', { value: w.id }, `${w.name} (${w.domain}, seed ${w.seed})`));
  } catch (e) { /* the list is optional */ }
}

async function main() {
  $('prompt-form').addEventListener('submit', submitPrompt);
  $('prompt').addEventListener('input', () => interpretTyped());
  for (const b of $('examples').querySelectorAll('button[data-prompt]')) {
    b.addEventListener('click', () => { $('prompt').value = b.dataset.prompt; $('prompt').focus(); interpretTyped(0); });
  }
  $('world-source').addEventListener('change', () => { $('scene-graph-label').hidden = $('world-source').value !== 'scene_graph'; });
  $('play').addEventListener('click', () => { send(view.paused ? 'resume' : 'pause'); view.paused = !view.paused; $('play').textContent = view.paused ? 'Play' : 'Pause'; });
  $('speed').addEventListener('change', () => send('speed', Number($('speed').value)));
  $('seek').addEventListener('input', () => { view.seeking = true; });
  $('seek').addEventListener('change', () => { view.seeking = false; send('seek', Number($('seek').value)); });
  $('colour-by').addEventListener('change', legend);
  $('share').addEventListener('click', (e) => { e.preventDefault(); navigator.clipboard?.writeText(location.href); toast('Link copied'); });
  legend();
  try {
    const info = await serverInfo;
    view.wsBase = info.websocket_url;
    const llm = info.generators.find((g) => g.name === 'llm');
    if (!llm || !llm.available) $('generator').querySelector('option[value=llm]').disabled = true;
  } catch (e) { /* the header says the server is not reachable */ }
  loadWorlds();
  loadRecent();
  requestAnimationFrame(draw);
  const m = location.hash.match(/card=(crd_[0-9a-z]+)/);
  if (m) openSharedCard(m[1]);
  else interpretTyped(0);
}

// A shared link: scenario cards play here; other cards (the catalogue's links were /#card=… before
// this page became the start page) open in the catalogue.
async function openSharedCard(id) {
  try {
    const card = await getJson(`/cards/${encodeURIComponent(id)}`);
    if (!card.trajectory_log) { location.replace(`catalogue.html#card=${id}`); return; }
    await openCard(id);
  } catch (e) {
    $('error').textContent = e.message;
  }
}

main();
