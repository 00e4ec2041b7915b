// Household viewer: pick a stored household or generate one (a job, with its progress), draw the
// house (rooms, walls, doors, receptacles) with every object where it is at the chosen time
// (GET …/objects?t=), the residents' schedules as a timeline, and the §V-A statistics as plots.
// Plain ES module, no build step.
import { $, getJson, postJson, jobText, waitForJob, setStatus, showLegend, COLOURS, drawPlan, planFromHousehold, fromHouse } from './common.js';

const ROLE_GROUPS = {
  sleep: ['sleep', 'nap'],
  away: ['leave_home'],
  meal: ['breakfast_prep', 'breakfast', 'lunch_prep', 'lunch', 'dinner_prep', 'dinner', 'meal_setup', 'snack', 'hot_drink', 'dish_cleanup'],
  hygiene: ['wake', 'morning_hygiene', 'evening_hygiene', 'dress', 'toilet', 'bedtime', 'medication'],
  chores: ['chore', 'laundry', 'childcare', 'pet', 'arrive', 'depart'],
  work: ['work', 'study'],
  leisure: ['leisure', 'hobby', 'exercise', 'social_call', 'social', 'prayer'],
};
const GROUP_COLOURS = COLOURS.activity;
// `plan` is the household's house converted to the plan shape on arrival (common.js); objects
// carry `at`, their place in plan coordinates.
const state = { id: null, household: null, plan: null, objects: null, t: 0, transform: null, drawn: {}, request: 0 };
window.household = state;  // for tests and the console

function groupOf(role) {
  for (const [g, roles] of Object.entries(ROLE_GROUPS)) if (roles.includes(role)) return g;
  return 'leisure';
}

function hashColour(text) {
  let h = 0;
  for (const c of text) h = (h * 31 + c.charCodeAt(0)) >>> 0;
  return `hsl(${h % 360}, 65%, 45%)`;
}

function clock(t, firstDay) {
  const days = ['Monday', 'Tuesday', 'Wednesday', 'Thursday', 'Friday', 'Saturday', 'Sunday'];
  const d = Math.floor(t / 86400), rest = t - d * 86400;
  const name = days[(days.indexOf(firstDay) + d) % 7].slice(0, 3);
  const hh = String(Math.floor(rest / 3600)).padStart(2, '0'), mm = String(Math.floor((rest % 3600) / 60)).padStart(2, '0');
  return `${name} ${hh}:${mm}`;
}

// ---- floor plan ----

function drawHouse() {
  if (!state.plan) return;
  state.transform = drawPlan($('plan'), state.plan, { entityLabels: false });
  drawObjects();
}

function drawObjects() {
  const canvas = $('plan'), ctx = canvas.getContext('2d'), t = state.transform;
  if (!state.objects || !t) return;
  const drawn = {};
  for (const o of state.objects.objects) {
    const [x, y] = t.toPx(o.at);
    ctx.beginPath();
    ctx.arc(x, y, 4.5, 0, 2 * Math.PI);
    ctx.fillStyle = hashColour(o.type);
    ctx.fill();
    ctx.strokeStyle = '#fff';
    ctx.lineWidth = 1;
    ctx.stroke();
    drawn[o.id] = [Math.round(x * 10) / 10, Math.round(y * 10) / 10];
  }
  state.drawn = drawn;
  canvas.dataset.t = String(state.objects.t);
  canvas.dataset.ready = '1';
}

async function showTime(t) {
  state.t = t;
  const h = state.household;
  $('clock').textContent = clock(t, h.first_day);
  drawTimeline();
  const ticket = ++state.request;
  const objects = await getJson(`/households/${state.id}/objects?t=${t}`);
  if (ticket !== state.request) return;  // a later slider position is already on its way
  state.objects = { ...objects, objects: objects.objects.map((o) => ({ ...o, at: fromHouse(o.position.x, o.position.z) })) };
  drawHouse();
  const events = await getJson(`/households/${state.id}/events?from=${Math.max(0, t - 3600)}&to=${Math.max(1, t)}&page_size=100`);
  if (ticket !== state.request) return;
  const lines = [];
  for (const e of events.items) for (const m of e.relocations) {
    if (e.end <= t) lines.push(`${clock(e.end, h.first_day)} · ${h.residents[e.resident].name.split(' ')[0]} (${e.activity}): ${m.object.split('|')[0]} → ${m.to.split('|')[0]}`);
  }
  $('moves').textContent = lines.length ? '' : 'no moves';
  for (const l of lines) { const div = document.createElement('div'); div.textContent = l; $('moves').appendChild(div); }
}

// ---- timeline ----

function drawTimeline() {
  const h = state.household;
  const canvas = $('timeline'), ctx = canvas.getContext('2d');
  const rows = h.schedules.length, rowH = 26, left = 90, top = 18;
  canvas.height = top + rows * rowH + 6;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const width = canvas.width - left - 8, scale = width / h.end;
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillStyle = '#6b7480';
  for (let d = 0; d <= h.days; d++) {
    const x = left + d * 86400 * scale;
    ctx.fillRect(x, top - 4, 1, rows * rowH + 4);
    if (d < h.days) ctx.fillText(clock(d * 86400, h.first_day).slice(0, 3), x + 3, top - 6);
  }
  h.schedules.forEach((s, i) => {
    const y = top + i * rowH;
    ctx.fillStyle = '#1d232b';
    ctx.fillText(h.residents[i].name.split(' ')[0], 4, y + rowH / 2 + 4);
    for (const e of s.entries) {
      ctx.fillStyle = GROUP_COLOURS[groupOf(e.role)];
      ctx.fillRect(left + e.start * scale, y + 3, Math.max(1, (e.end - e.start) * scale), rowH - 6);
    }
  });
  const x = left + state.t * scale;
  ctx.fillStyle = COLOURS.mark.now;
  ctx.fillRect(x - 1, top - 6, 2, rows * rowH + 8);
  canvas.dataset.rows = String(rows);
  canvas.onclick = (ev) => {
    const r = canvas.getBoundingClientRect();
    const cx = (ev.clientX - r.left) * canvas.width / r.width;
    if (cx < left) return;
    const t = Math.round(Math.min(h.end, Math.max(0, (cx - left) / scale)) / 300) * 300;
    $('time').value = String(t);
    showTime(t).catch((e) => setStatus(e.message));
  };
}

function drawLegend() {
  showLegend($('legend'), Object.entries(GROUP_COLOURS));
}

// ---- statistics ----

function barChart(svg, entries, colour) {
  const W = svg.clientWidth || 400, H = svg.clientHeight || 200, pad = 24;
  svg.setAttribute('viewBox', `0 0 ${W} ${H}`);
  const max = Math.max(1e-9, ...entries.map(([, v]) => v));
  const bw = (W - 2 * pad) / Math.max(1, entries.length);
  const parts = [];
  entries.forEach(([k, v], i) => {
    const h = (H - 2 * pad) * v / max;
    const x = pad + i * bw, y = H - pad - h;
    parts.push(`<rect x="${x + 1}" y="${y}" width="${Math.max(1, bw - 2)}" height="${h}" fill="${colour}"><title>${k}: ${v}</title></rect>`);
    if (entries.length <= 24 || i % 2 === 0) parts.push(`<text x="${x + bw / 2}" y="${H - pad + 12}" font-size="10" text-anchor="middle">${k}</text>`);
  });
  parts.push(`<text x="${pad}" y="${pad - 8}" font-size="10">max ${Math.round(max * 100) / 100}</text>`);
  svg.innerHTML = parts.join('');
  svg.dataset.bars = String(entries.length);
}

async function showStatistics() {
  const s = await getJson(`/households/${state.id}/statistics`);
  const per = Object.entries(s.objects_per_event.percent_by_count).map(([k, v]) => [Number(k), v]).sort((a, b) => a[0] - b[0]);
  barChart($('per-event'), per, '#2a6fdb');
  const hist = Object.entries(s.receptacle_types_per_object_type.histogram).map(([k, v]) => [Number(k), v]).sort((a, b) => a[0] - b[0]);
  barChart($('receptacle-types'), hist, '#2e9d5b');
  $('stats-text').textContent = `objects per event ${s.objects_per_event.mean} ± ${s.objects_per_event.sd} (paper ${s.paper.objects_per_event.mean} ± ${s.paper.objects_per_event.sd}); ` +
    `${s.activities.names} activity names, ${s.activities.primaries} after merging; residents' age ${s.age.mean} ± ${s.age.sd}`;
}

// ---- households ----

async function openHousehold(id) {
  setStatus(`loading ${id}…`);
  $('plan').dataset.ready = '0';
  const h = await getJson(`/households/${id}`);
  state.id = id;
  state.household = h;
  state.plan = planFromHousehold(h.house);
  const url = new URL(location.href);
  url.searchParams.set('id', id);
  history.replaceState(null, '', url);
  for (const li of $('households').children) li.classList.toggle('current', li.dataset.id === id);
  $('summary').textContent = `${id}: ${h.rooms} rooms, ${h.objects} objects, ${h.residents.length} residents, ${h.days} days from ${h.first_day}; ` +
    `${h.events} events moved objects ${h.relocations} times`;
  $('residents').innerHTML = '';
  h.residents.forEach((r) => {
    const li = document.createElement('li');
    li.innerHTML = `<b></b> <span class="muted"></span><br><small class="muted"></small>`;
    li.querySelector('b').textContent = r.name;
    li.querySelector('span').textContent = `${r.age}, bedroom ${r.bedroom ?? '—'}`;
    li.querySelector('small').textContent = r.occupation;
    $('residents').appendChild(li);
  });
  const slider = $('time');
  slider.max = String(h.end);
  const start = Math.min(h.end, 8 * 3600);
  slider.value = String(start);
  drawLegend();
  await showTime(start);
  showStatistics().catch((e) => setStatus(e.message));
  setStatus(`household ${id}`);
}

async function listHouseholds() {
  const page = await getJson('/households?page_size=50');
  const list = $('households');
  list.innerHTML = '';
  for (const item of page.items) {
    const li = document.createElement('li');
    li.dataset.id = item.id;
    const s = item.summary || {};
    li.textContent = `${item.id} · ${s.rooms ?? '?'} rooms · ${(s.residents || []).map((r) => r.name.split(' ')[0]).join(', ')}`;
    li.addEventListener('click', () => openHousehold(item.id).catch((e) => setStatus(e.message)));
    list.appendChild(li);
  }
}

async function create(ev) {
  ev.preventDefault();
  const body = {
    rooms: Number($('rooms').value), residents: Number($('residents-n').value), days: Number($('days').value),
    start_weekday: $('weekday').value, seed: Number($('seed').value),
  };
  setStatus('queued…');
  const job = await postJson('/households', body);
  const done = await waitForJob(job.id, { bar: $('progress'), onUpdate: (j) => setStatus(jobText(j)) });
  await listHouseholds();
  await openHousehold(done.result.household_id);
}

let pending = null;
$('time').addEventListener('input', () => {
  const t = Number($('time').value);
  clearTimeout(pending);
  pending = setTimeout(() => showTime(t).catch((e) => setStatus(e.message)), 60);
});
$('create').addEventListener('submit', (ev) => create(ev).catch((e) => setStatus(e.message)));

(async () => {
  try {
    await listHouseholds();
    const id = new URL(location.href).searchParams.get('id');
    if (id) await openHousehold(id);
  } catch (e) {
    setStatus(e.message);
  }
})();
