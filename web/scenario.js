// socsim text-to-scenario page: prompt → job (progress) → scenario card → a live session of the
// card's recorded trajectories streamed over WebSocket, drawn over the world on a Canvas 2D with
// interpolation between frames and trails; play/pause/speed/seek go over the socket. Plain
// browser JavaScript, no build step.
'use strict';

const api = '/api/v1';
const $ = (id) => document.getElementById(id);
const STATE_COLOURS = {
  walking: '#1c7ed6', standing: '#868e96', queuing: '#e8590c', sitting: '#2b8a3e', interacting: '#ae3ec9',
  evacuating: '#e03131', waiting: '#f59f00', running: '#c2255c', exited: '#ced4da',
};
const ROLE_PALETTE = ['#1c7ed6', '#e8590c', '#2b8a3e', '#ae3ec9', '#e03131', '#0c8599', '#f59f00', '#5f3dc4', '#495057', '#c2255c'];
const TRAIL = 24;  // frames of history drawn per agent

const view = {
  card: null, world: null, base: null, transform: null, ws: null, wsBase: null, session: null,
  prev: new Map(), curr: new Map(), currAt: 0, interval: 0.1, t: 0, paused: false, trails: new Map(),
  roles: [], duration: 60, frames: 0, seeking: false,
};

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v; else if (k.startsWith('on')) e.addEventListener(k.slice(2), v); else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

async function call(method, url, body) {
  const r = await fetch(url, {
    method, headers: body ? { 'Content-Type': 'application/json' } : {}, body: body ? JSON.stringify(body) : undefined,
  });
  const text = await r.text();
  const json = text ? JSON.parse(text) : {};
  if (!r.ok) {
    const where = (json.errors || []).map((e) => `${e.pointer || e.parameter || ''}: ${e.message}`).join('\n');
    throw new Error(`${json.title || r.statusText}: ${json.detail || ''}${where ? '\n' + where : ''}`);
  }
  return json;
}

function toast(text) {
  const t = $('toast');
  t.textContent = text;
  t.hidden = false;
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => { t.hidden = true; }, 3000);
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
  $('progress').hidden = false;
  $('progress').value = 0;
  try {
    const job = await call('POST', `${api}/scenarios`, body);
    const done = await followJob(job.id);
    if (done.status !== 'succeeded') throw new Error(done.error ? `${done.error.title}: ${done.error.detail}` : done.status);
    await openCard(done.result.card_id);
    loadRecent();
  } catch (err) {
    $('error').textContent = err.message;
    $('job-status').textContent = '';
  } finally {
    $('generate').disabled = false;
    $('progress').hidden = true;
  }
}

async function followJob(id) {
  for (;;) {
    const job = await call('GET', `${api}/jobs/${id}`);
    $('progress').value = job.progress || 0;
    $('job-status').textContent = `${job.status}: ${job.message || ''}`;
    if (['succeeded', 'failed', 'cancelled'].includes(job.status)) return job;
    await new Promise((r) => setTimeout(r, 250));
  }
}

// ---------------------------------------------------------------- card → session → stream
async function openCard(id) {
  stopStream();
  const card = await call('GET', `${api}/cards/${encodeURIComponent(id)}`);
  view.card = card;
  history.replaceState(null, '', `#card=${id}`);
  $('card-title').textContent = card.title;
  $('card-description').textContent = `${card.description} Seed ${card.seed}, ${card.generator.name}${card.generator.model ? ' (' + card.generator.model + ')' : ''}.`;
  $('catalogue-link').href = `index.html#card=${id}`;
  $('share').href = `scenario.html#card=${id}`;
  $('csv').href = `${api}/cards/${id}/export?format=csv`;
  view.world = card.world;
  view.duration = card.trajectory_log?.duration_s || 60;
  $('seek').max = String(view.duration);
  prepareStage();
  showMetrics(card.metrics);
  if (!card.trajectory_log) { $('stream-status').textContent = 'this card has no trajectory log'; return; }
  const session = await call('POST', `${api}/simulations`, { card_id: id, speed: Number($('speed').value) });
  connect(session);
}

function wsUrl(session) {
  const u = session.websocket_url || session.ws_url || `/ws/simulations/${session.id}`;
  if (/^wss?:/.test(u)) return u;
  return view.wsBase.replace(/\/ws$/, '') + u;
}

function connect(session) {
  view.session = session;
  const ws = new WebSocket(wsUrl(session));
  view.ws = ws;
  $('stream-status').textContent = 'connecting…';
  ws.onopen = () => { $('stream-status').textContent = 'streaming'; $('play').disabled = false; };
  ws.onclose = () => { if (view.ws === ws) { $('stream-status').textContent = 'stream ended'; $('play').disabled = true; } };
  ws.onmessage = (m) => {
    if (typeof m.data !== 'string') return;
    const msg = JSON.parse(m.data);
    if (msg.type === 'hello') {
      view.roles = msg.roles || [];
      if (msg.frame_hz) view.interval = 1 / msg.frame_hz;
      if (msg.duration_s) { view.duration = msg.duration_s; $('seek').max = String(msg.duration_s); }
      $('seek').disabled = !msg.seekable;
      legend();
    } else if (msg.type === 'frame') {
      onFrame(msg);
    } else if (msg.type === 'status') {
      view.paused = !!msg.paused;
      $('play').textContent = view.paused ? 'Play' : 'Pause';
    } else if (msg.type === 'end') {
      $('stream-status').textContent = `ended (${msg.reason || 'done'})`;
    }
  };
}

function stopStream() {
  if (view.ws) { const ws = view.ws; view.ws = null; ws.close(); }
  view.prev.clear(); view.curr.clear(); view.trails.clear();
}

function send(action, value) {
  if (view.ws && view.ws.readyState === WebSocket.OPEN) view.ws.send(JSON.stringify(value === undefined ? { action } : { action, value }));
}

function onFrame(msg) {
  if (msg.t < view.t - 1e-6) { view.trails.clear(); view.prev.clear(); }  // a seek backwards
  view.prev = view.curr;
  view.curr = new Map();
  for (const a of msg.agents) {
    view.curr.set(a.id, a);
    let trail = view.trails.get(a.id);
    if (!trail) { trail = []; view.trails.set(a.id, trail); }
    trail.push(a.x, a.y);
    if (trail.length > 2 * TRAIL) trail.splice(0, 2);
  }
  for (const id of view.trails.keys()) if (!view.curr.has(id)) view.trails.delete(id);
  view.currAt = performance.now();
  view.t = msg.t;
  view.frames += 1;
  if (!view.seeking) $('seek').value = String(msg.t);
  $('clock').textContent = `${msg.t.toFixed(1)} s · ${view.curr.size} people`;
  liveCounts();
}

// ---------------------------------------------------------------- drawing
function prepareStage() {
  const stage = $('stage');
  view.base = document.createElement('canvas');
  view.base.width = stage.width;
  view.base.height = stage.height;
  // Zone names only: entity labels would hide the people standing at them.
  view.transform = window.socsimWorld.drawWorld(view.base, view.world || {}, { entityLabels: false });
}

function colourOf(a) {
  if ($('colour-by').value === 'role') {
    const i = Math.max(0, view.roles.indexOf(a.role));
    return ROLE_PALETTE[i % ROLE_PALETTE.length];
  }
  return STATE_COLOURS[a.state] || '#343a40';
}

function legend() {
  const byRole = $('colour-by').value === 'role';
  const items = byRole ? view.roles.map((r, i) => [r, ROLE_PALETTE[i % ROLE_PALETTE.length]]) : Object.entries(STATE_COLOURS);
  $('legend').replaceChildren(...items.map(([name, c]) => el('span', {}, el('i', { class: 'swatch', style: `background:${c}` }), name)));
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
  if ($('trails').checked) {
    ctx.lineWidth = 1;
    for (const [id, trail] of view.trails) {
      if (trail.length < 4) continue;
      const a = view.curr.get(id);
      ctx.strokeStyle = a ? colourOf(a) + '66' : '#adb5bd66';
      ctx.beginPath();
      ctx.moveTo(px(trail[0]), py(trail[1]));
      for (let i = 2; i < trail.length; i += 2) ctx.lineTo(px(trail[i]), py(trail[i + 1]));
      ctx.stroke();
    }
  }
  const r = Math.max(2.5, 0.25 * t.scale);
  for (const [id, a] of view.curr) {
    const p = view.prev.get(id);
    const x = p ? p.x + (a.x - p.x) * alpha : a.x;
    const y = p ? p.y + (a.y - p.y) * alpha : a.y;
    ctx.fillStyle = colourOf(a);
    ctx.beginPath();
    ctx.arc(px(x), py(y), r, 0, 2 * Math.PI);
    ctx.fill();
    ctx.strokeStyle = '#212529';
    ctx.beginPath();
    ctx.moveTo(px(x), py(y));
    ctx.lineTo(px(x) + Math.cos(a.yaw) * r * 1.6, py(y) - Math.sin(a.yaw) * r * 1.6);
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
  const table = el('table', { class: 'metrics' },
    el('tr', {}, el('th', {}, 'who'), ...cols.map((c) => el('th', {}, c.replace(/_/g, ' ')))),
    ...rows.map(([who, s]) => el('tr', {}, el('td', {}, who), ...cols.map((c) => el('td', {}, fmt(s[c]))))));
  $('metrics').replaceChildren(
    el('p', {}, `${fmt(m.duration)} s simulated, mean speed ${fmt(m.avg_pedestrian_velocity)} m/s.`),
    table, el('p', { id: 'live-counts', class: 'muted' }, ''));
}

function liveCounts() {
  const counts = {};
  for (const a of view.curr.values()) counts[a.state] = (counts[a.state] || 0) + 1;
  const node = $('live-counts');
  if (node) node.textContent = 'now: ' + Object.entries(counts).map(([s, n]) => `${n} ${s}`).join(', ');
}

// ---------------------------------------------------------------- lists
async function loadRecent() {
  try {
    const page = await call('GET', `${api}/cards?tag=scenario&page_size=10`);
    $('recent').replaceChildren(...page.items.map((c) => el('li', { 'data-id': c.id, onclick: () => openCard(c.id).catch((e) => toast(e.message)) },
      el('span', { class: 'title' }, c.title), ' ', el('span', { class: 'muted' }, c.domain || ''))));
  } catch (e) {
    toast(`Could not list cards: ${e.message}`);
  }
}

async function loadWorlds() {
  try {
    const page = await call('GET', `${api}/worlds?page_size=50`);
    for (const w of page.items) $('world-id').append(el('option', { value: w.id }, `${w.name} (${w.domain}, seed ${w.seed})`));
  } catch (e) { /* the list is optional */ }
}

async function main() {
  $('prompt-form').addEventListener('submit', submitPrompt);
  $('world-source').addEventListener('change', () => { $('scene-graph-label').hidden = $('world-source').value !== 'scene_graph'; });
  $('play').addEventListener('click', () => { send(view.paused ? 'resume' : 'pause'); view.paused = !view.paused; $('play').textContent = view.paused ? 'Play' : 'Pause'; });
  $('speed').addEventListener('change', () => send('speed', Number($('speed').value)));
  $('seek').addEventListener('input', () => { view.seeking = true; });
  $('seek').addEventListener('change', () => { view.seeking = false; send('seek', Number($('seek').value)); });
  $('colour-by').addEventListener('change', legend);
  $('share').addEventListener('click', (e) => { e.preventDefault(); navigator.clipboard?.writeText(location.href); toast('Link copied'); });
  legend();
  try {
    const info = await call('GET', `${api}/info`);
    view.wsBase = info.websocket_url;
    const llm = info.generators.find((g) => g.name === 'llm');
    if (!llm || !llm.available) $('generator').querySelector('option[value=llm]').disabled = true;
    $('server-info').textContent = `v${info.version}`;
  } catch (e) {
    $('server-info').textContent = 'server not reachable';
  }
  loadWorlds();
  loadRecent();
  requestAnimationFrame(draw);
  const m = location.hash.match(/card=(crd_[0-9a-z]+)/);
  if (m) openCard(m[1]).catch((e) => { $('error').textContent = e.message; });
}

main();
