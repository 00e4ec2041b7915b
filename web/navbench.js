// Navigation benchmark viewer: runs a benchmark job (or opens one from ?job=ID), shows the table
// in the shape of paper 000 Table I, and replays one episode on a canvas — the house, the grid of
// reachable points, the agent's path step by step, the receptacles visited and the target.
// Plain ES module, no build step.
import { $, getJson, postJson, jobText, waitForJob, setStatus, showLegend, COLOURS, drawPlan, planFromHousehold, fromHouse } from './common.js';

// `plan` is the episode's house converted to the plan shape on arrival (common.js).
const state = { job: null, result: null, episode: null, plan: null, method: null, step: 0, timer: null };
window.navbench = state;  // for tests and the console

function renderTable(result) {
  // Table I's order (JSON objects come back sorted by key).
  const order = ['Uniform+Greedy', 'SP+OSG', 'SP+CEG', 'Hint+OSG', 'Hint+CEG', 'Posterior+OSG', 'Posterior+CEG'];
  const rank = (k) => (order.indexOf(k) < 0 ? order.length : order.indexOf(k));
  const entries = Object.entries(result.methods).sort((a, b) => rank(a[0]) - rank(b[0]));
  // Ours with the half-width of the 95 % interval over scenes; paper 000 Table I beside (the
  // server sends it per method as `paper`; its hint rows are LLM + OSG / LLM + CEG).
  const ci = (v, h, d) => (h === undefined ? v.toFixed(d) : `${v.toFixed(d)} <small>± ${h.toFixed(d)}</small>`);
  const paper = (m, k, d) => (m.paper ? m.paper[k].toFixed(d) : '—');
  const rows = entries.map(([key, m]) =>
    `<tr><td>${key === 'Uniform+Greedy' ? 'Greedy (Uniform)' : key}</td><td>${ci(m.EL, m.EL_ci95, 1)}</td><td>${ci(m.SR, m.SR_ci95, 2)}</td><td>${ci(m.SPL, m.SPL_ci95, 2)}</td>` +
    `<td class="paper">${paper(m, 'EL', 1)}</td><td class="paper">${paper(m, 'SR', 2)}</td><td class="paper">${paper(m, 'SPL', 2)}</td></tr>`);
  $('table').innerHTML = `<p>${result.split} split: ${result.scenes} scenes, ${result.tasks} tasks, seed ${result.seed} · ± is the 95 % interval over scenes</p>` +
    `<table class="data"><thead><tr><th>Method</th><th>EL ↓</th><th>SR (%) ↑</th><th>SPL ↑</th><th>paper EL</th><th>paper SR</th><th>paper SPL</th></tr></thead>` +
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

async function openJob(id, n) {
  state.job = id;
  setStatus('loading the benchmark…');
  const job = await waitForJob(id, { onUpdate: (j) => setStatus(jobText(j)) });
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
  state.plan = planFromHousehold(episode.house);
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
    // Every resident answers, one a line ("<name>: <answer>").
    `<i>hints:</i><br>${e.hint.split('\n').map((a) => `“${a}”`).join('<br>')}<br>` +
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
  const reached = reachedBy(state.step);
  const mark = COLOURS.mark;
  const t = drawPlan(canvas, state.plan, {
    entityLabels: false,
    entityFill: (r) => (r.name === e.target.receptacle ? mark.target : reached.includes(r.name) ? mark.visited : undefined),
    underlay: (ctx, t) => {  // the reachable points of the grid
      ctx.fillStyle = mark.free;
      for (let c = 0; c < g.free.length; c++) {
        if (g.free[c] !== '1') continue;
        const [x, y] = t.toPx(fromHouse(g.origin[0] + ((c % g.width) + 0.5) * g.cell, g.origin[1] + (Math.floor(c / g.width) + 0.5) * g.cell));
        ctx.fillRect(x - 1, y - 1, 2, 2);
      }
    },
  });
  const at = (x, z) => t.toPx(fromHouse(x, z));
  const ctx = canvas.getContext('2d');
  ctx.fillStyle = '#000';
  ctx.font = 'bold 13px system-ui, sans-serif';
  for (const r of state.plan.entities) {
    const order = reached.indexOf(r.name);
    if (order < 0) continue;
    const [x, y] = t.toPx(r.pose);
    ctx.fillText(String(order + 1), x - 4, y + 4);
  }
  // The path up to the current step, then the agent as an arrow (headings +x, +z, -x, -z: on screen
  // z points down, as in the plan).
  ctx.strokeStyle = mark.path;
  ctx.lineWidth = 2;
  ctx.beginPath();
  for (let i = 0; i <= state.step; i++) {
    const [x, y] = at(m.path[i][0], m.path[i][1]);
    i ? ctx.lineTo(x, y) : ctx.moveTo(x, y);
  }
  ctx.stroke();
  const [sx, sy] = at(m.path[0][0], m.path[0][1]);
  ctx.fillStyle = mark.path;
  ctx.beginPath();
  ctx.arc(sx, sy, 4, 0, 2 * Math.PI);
  ctx.fill();
  const [ax, ay] = at(m.path[state.step][0], m.path[state.step][1]);
  const dir = [[1, 0], [0, 1], [-1, 0], [0, -1]][m.path[state.step][2]];
  ctx.fillStyle = mark.agent;
  ctx.beginPath();
  ctx.moveTo(ax + dir[0] * 10, ay + dir[1] * 10);
  ctx.lineTo(ax - dir[1] * 6 - dir[0] * 4, ay + dir[0] * 6 - dir[1] * 4);
  ctx.lineTo(ax + dir[1] * 6 - dir[0] * 4, ay - dir[0] * 6 - dir[1] * 4);
  ctx.closePath();
  ctx.fill();
  // Target marker.
  const [tx, ty] = at(e.target.x, e.target.z);
  ctx.strokeStyle = mark.target;
  ctx.lineWidth = 2;
  ctx.setLineDash([4, 4]);
  ctx.beginPath();
  ctx.arc(tx, ty, 1.5 * t.scale, 0, 2 * Math.PI);
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
    const job = await postJson('/navbench', { split: $('split').value, scenes: Number($('scenes').value), seed: Number($('seed').value) });
    await openJob(job.id, 0);
  } catch (err) {
    setStatus(`error: ${err.message}`);
  }
});

showLegend($('legend'), [["target's receptacle", COLOURS.mark.target], ['visited', COLOURS.mark.visited],
  ['agent path', COLOURS.mark.path], ['other receptacles', COLOURS.plan.furniture]]);
const params = new URLSearchParams(location.search);
if (params.get('job')) {
  openJob(params.get('job'), Number(params.get('n') ?? 0)).catch((err) => setStatus(`error: ${err.message}`));
}
