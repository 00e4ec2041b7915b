// Navigation benchmark viewer: runs a benchmark job (or opens one from ?job=ID), shows the table
// in the shape of paper 000 Table I, and replays one episode on a canvas — the house, the grid of
// reachable points, the agent's path step by step, the receptacles visited and the target.
const api = '/api/v1';
const $ = (id) => document.getElementById(id);
const roomColours = { Kitchen: '#fff4d6', LivingRoom: '#e9f3e4', Bedroom: '#e6ecfa', Bathroom: '#e3f5f7' };
const state = { job: null, result: null, episode: null, method: null, step: 0, timer: null };
window.navbench = state;  // for tests and the console

function setStatus(text) { $('status').textContent = text; }

async function getJson(path) {
  const r = await fetch(api + path);
  const body = await r.json();
  if (!r.ok) throw new Error(body.detail || body.title || `HTTP ${r.status}`);
  return body;
}

function renderTable(result) {
  // Table I's order (JSON objects come back sorted by key).
  const order = ['Uniform+Greedy', 'SP+OSG', 'SP+CEG', 'Hint+OSG', 'Hint+CEG', 'Posterior+OSG', 'Posterior+CEG'];
  const rank = (k) => (order.indexOf(k) < 0 ? order.length : order.indexOf(k));
  const entries = Object.entries(result.methods).sort((a, b) => rank(a[0]) - rank(b[0]));
  const rows = entries.map(([key, m]) =>
    `<tr><td>${key === 'Uniform+Greedy' ? 'Greedy (Uniform)' : key}</td><td>${m.EL.toFixed(1)}</td><td>${m.SR.toFixed(2)}</td><td>${m.SPL.toFixed(2)}</td></tr>`);
  $('table').innerHTML = `<p>${result.split} split: ${result.scenes} scenes, ${result.tasks} tasks, seed ${result.seed}</p>` +
    `<table class="scores"><thead><tr><th>Method</th><th>EL ↓</th><th>SR (%) ↑</th><th>SPL ↑</th></tr></thead>` +
    `<tbody>${rows.join('')}</tbody></table>`;
  const list = $('episodes');
  list.innerHTML = '';
  for (const e of result.episodes || []) {
    const li = document.createElement('li');
    const solved = Object.values(e.outcomes).filter((o) => o.success).length;
    li.textContent = `#${e.task} · scene ${e.scene} · ${e.target} · ${solved}/${Object.keys(e.outcomes).length} methods found it`;
    li.dataset.n = e.task;
    li.addEventListener('click', () => openEpisode(e.task));
    list.appendChild(li);
  }
}

async function waitForJob(id) {
  for (;;) {
    const job = await getJson(`/jobs/${id}`);
    if (job.status === 'succeeded') return job;
    if (job.status === 'failed' || job.status === 'cancelled') throw new Error(job.error?.detail || job.status);
    setStatus(`${job.status}: ${job.message || ''} ${Math.round((job.progress || 0) * 100)} %`);
    await new Promise((r) => setTimeout(r, 500));
  }
}

async function openJob(id, n) {
  state.job = id;
  setStatus('loading the benchmark…');
  const job = await waitForJob(id);
  state.result = job.result;
  renderTable(job.result);
  setStatus(`benchmark ${id}: ${job.result.tasks} tasks`);
  if (job.result.tasks > 0) await openEpisode(Number.isInteger(n) && n >= 0 && n < job.result.tasks ? n : 0);
}

async function openEpisode(n) {
  setStatus(`loading episode ${n}…`);
  $('replay').dataset.ready = '0';
  const episode = await getJson(`/navbench/${state.job}/episodes/${n}`);
  state.episode = episode;
  for (const li of $('episodes').children) li.classList.toggle('current', Number(li.dataset.n) === n);
  const select = $('method');
  const keep = state.method;
  select.innerHTML = '';
  for (const key of Object.keys(episode.methods)) select.add(new Option(key, key));
  state.method = keep && episode.methods[keep] ? keep : Object.keys(episode.methods)[0];
  select.value = state.method;
  const url = new URL(location.href);
  url.searchParams.set('job', state.job);
  url.searchParams.set('n', String(n));
  history.replaceState(null, '', url);
  showMethod();
  setStatus(`episode ${n}`);
}

function showMethod() {
  const e = state.episode;
  const m = e.methods[state.method];
  $('episode-info').innerHTML =
    `<b>${e.target.type}</b> on <code>${e.target.receptacle}</code> at ${e.clock} · scene ${e.scene} · shortest ${e.shortest} steps<br>` +
    `<i>hint:</i> “${e.hint}”<br>` +
    `<b>${state.method}</b>: ${m.success ? 'found' : 'not found'} in ${m.steps} steps, SPL ${(m.spl * 100).toFixed(1)}`;
  const slider = $('step');
  slider.max = String(m.path.length - 1);
  stopPlaying();
  setStep(m.path.length - 1);
}

function setStep(k) {
  const m = state.episode.methods[state.method];
  state.step = Math.max(0, Math.min(k, m.path.length - 1));
  $('step').value = String(state.step);
  $('step-label').textContent = `step ${state.step} / ${m.path.length - 1}`;
  draw();
}

// The visited receptacles the agent has reached by step k.
function reachedBy(k) {
  return state.episode.methods[state.method].visited.filter((v) => v.step <= k).map((v) => v.receptacle);
}

function draw() {
  const e = state.episode;
  const m = e.methods[state.method];
  const canvas = $('replay');
  const g = e.house.grid;
  const w = g.width * g.cell, d = g.depth * g.cell;
  const pad = 20;
  const scale = Math.min((canvas.width - 2 * pad) / w, (canvas.height - 2 * pad) / d);
  const X = (x) => pad + (x - g.origin[0]) * scale;
  const Z = (z) => pad + (z - g.origin[1]) * scale;
  const ctx = canvas.getContext('2d');
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = '#fafafa';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  for (const room of e.house.rooms) {
    ctx.beginPath();
    room.floor.forEach(([x, z], i) => (i ? ctx.lineTo(X(x), Z(z)) : ctx.moveTo(X(x), Z(z))));
    ctx.closePath();
    ctx.fillStyle = roomColours[room.type] || '#eee';
    ctx.fill();
    const cx = room.floor.reduce((s, p) => s + p[0], 0) / room.floor.length;
    const cz = room.floor.reduce((s, p) => s + p[1], 0) / room.floor.length;
    ctx.fillStyle = '#999';
    ctx.font = '12px sans-serif';
    ctx.fillText(room.type, X(cx) - 24, Z(cz));
  }
  // Reachable points of the grid.
  ctx.fillStyle = '#c8c8c8';
  for (let c = 0; c < g.free.length; c++) {
    if (g.free[c] !== '1') continue;
    const x = g.origin[0] + ((c % g.width) + 0.5) * g.cell, z = g.origin[1] + (Math.floor(c / g.width) + 0.5) * g.cell;
    ctx.fillRect(X(x) - 1, Z(z) - 1, 2, 2);
  }
  ctx.strokeStyle = '#222';
  ctx.lineWidth = 3;
  for (const [x0, z0, x1, z1] of e.house.walls) {
    ctx.beginPath();
    ctx.moveTo(X(x0), Z(z0));
    ctx.lineTo(X(x1), Z(z1));
    ctx.stroke();
  }
  const reached = reachedBy(state.step);
  for (const r of e.house.receptacles) {
    const order = reached.indexOf(r.id);
    ctx.fillStyle = r.id === e.target.receptacle ? '#d33' : order >= 0 ? '#2a6' : '#bbb';
    ctx.fillRect(X(r.x - r.size_x / 2), Z(r.z - r.size_z / 2), r.size_x * scale, r.size_z * scale);
    if (order >= 0) {
      ctx.fillStyle = '#000';
      ctx.font = 'bold 13px sans-serif';
      ctx.fillText(String(order + 1), X(r.x) - 4, Z(r.z) + 4);
    }
  }
  // The path up to the current step, then the agent as an arrow.
  ctx.strokeStyle = '#36c';
  ctx.lineWidth = 2;
  ctx.beginPath();
  for (let i = 0; i <= state.step; i++) {
    const [x, z] = m.path[i];
    i ? ctx.lineTo(X(x), Z(z)) : ctx.moveTo(X(x), Z(z));
  }
  ctx.stroke();
  const [sx, sz] = m.path[0];
  ctx.fillStyle = '#36c';
  ctx.beginPath();
  ctx.arc(X(sx), Z(sz), 4, 0, 2 * Math.PI);
  ctx.fill();
  const [ax, az, heading] = m.path[state.step];
  const dir = [[1, 0], [0, 1], [-1, 0], [0, -1]][heading];
  const tip = [X(ax) + dir[0] * 10, Z(az) + dir[1] * 10];
  ctx.fillStyle = '#036';
  ctx.beginPath();
  ctx.moveTo(tip[0], tip[1]);
  ctx.lineTo(X(ax) - dir[1] * 6 - dir[0] * 4, Z(az) + dir[0] * 6 - dir[1] * 4);
  ctx.lineTo(X(ax) + dir[1] * 6 - dir[0] * 4, Z(az) - dir[0] * 6 - dir[1] * 4);
  ctx.closePath();
  ctx.fill();
  // Target marker.
  ctx.strokeStyle = '#d33';
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.arc(X(e.target.x), Z(e.target.z), 1.5 * scale, 0, 2 * Math.PI);
  ctx.setLineDash([4, 4]);
  ctx.stroke();
  ctx.setLineDash([]);

  const list = $('visited');
  list.innerHTML = '';
  for (const { receptacle: id, step } of m.visited) {
    const li = document.createElement('li');
    li.textContent = `${id} at step ${step}` + (id === e.target.receptacle ? ' (target)' : '');
    li.classList.toggle('reached', step <= state.step);
    list.appendChild(li);
  }
  canvas.dataset.ready = '1';
  canvas.dataset.step = String(state.step);
}

function stopPlaying() {
  if (state.timer) clearInterval(state.timer);
  state.timer = null;
  $('play').textContent = 'Play';
}

$('play').addEventListener('click', () => {
  if (state.timer) return stopPlaying();
  const m = state.episode?.methods[state.method];
  if (!m) return;
  if (state.step >= m.path.length - 1) setStep(0);
  $('play').textContent = 'Pause';
  state.timer = setInterval(() => {
    if (state.step >= m.path.length - 1) return stopPlaying();
    setStep(state.step + 1);
  }, 80);
});
$('step').addEventListener('input', (ev) => { stopPlaying(); setStep(Number(ev.target.value)); });
$('method').addEventListener('change', (ev) => { state.method = ev.target.value; showMethod(); });
$('run').addEventListener('submit', async (ev) => {
  ev.preventDefault();
  try {
    const r = await fetch(`${api}/navbench`, {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ split: $('split').value, scenes: Number($('scenes').value), seed: Number($('seed').value) }),
    });
    const body = await r.json();
    if (r.status !== 202) throw new Error(body.detail || `HTTP ${r.status}`);
    await openJob(body.id, 0);
  } catch (err) {
    setStatus(`error: ${err.message}`);
  }
});

const params = new URLSearchParams(location.search);
if (params.get('job')) {
  openJob(params.get('job'), Number(params.get('n') ?? 0)).catch((err) => setStatus(`error: ${err.message}`));
}
