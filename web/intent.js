// "What was understood": a ScenarioIntent (schemas/intent.schema.json, from POST
// /api/v1/scenarios/interpret or a card's `intent`) drawn as the prompt with the words it came from
// highlighted, then each group with its count, activity and place, the venue, what the world must
// hold, and the warnings for words that could not be used. Plain ES module, no build step.
import { $, el, showLegend } from './common.js';

// Highlight kinds, weakest first: where spans overlap, the later kind wins (a count inside its
// group, the venue or a feature inside a place phrase: "in the café", "at the reception desk").
const KINDS = [
  ['warning', 'not used', '#ffd8d8'],
  ['place', 'place', '#c5f6fa'],
  ['venue', 'venue', '#d3f9d8'],
  ['world', 'feature, room, object', '#ffe8cc'],
  ['only', 'only / except / density', '#eebefa'],
  ['group', 'people', '#d0ebff'],
  ['count', 'count', '#74c0fc'],
];
const RANK = Object.fromEntries(KINDS.map(([k], i) => [k, i]));

// Spans are byte offsets into the UTF-8 prompt; JavaScript indexes UTF-16 units. index[b] is the
// string index of byte b (bytes inside a character map to its start).
function byteIndex(text) {
  const index = [];
  let i = 0;
  for (const ch of text) {
    const bytes = new TextEncoder().encode(ch).length;
    for (let k = 0; k < bytes; k++) index.push(i);
    i += ch.length;
  }
  index.push(i);
  return index;
}

export function countText(c) {
  if (!c || c.kind === 'unspecified') return 'some';
  if (c.kind === 'exact') return String(c.value);
  if (c.kind === 'approx') return `about ${c.value}` + (c.min !== undefined ? ` (${c.min}–${c.max})` : '');
  if (c.kind === 'range') return `${c.min}–${c.max}`;
  return c.kind;
}

const words = (s) => String(s).replace(/_/g, ' ');

// The prompt as text runs, each char marked by the strongest kind whose span covers it.
function highlighted(intent) {
  const text = intent.prompt || '';
  const at = byteIndex(text);
  const kind = new Array(text.length).fill(null);
  const title = new Array(text.length).fill('');
  const mark = (span, k, why) => {
    if (!Array.isArray(span) || span.length !== 2) return;
    const a = at[Math.min(span[0], at.length - 1)], b = at[Math.min(span[1], at.length - 1)];
    for (let i = a; i < b; i++) {
      if (kind[i] === null || RANK[k] >= RANK[kind[i]]) { kind[i] = k; title[i] = why; }
    }
  };
  for (const w of intent.warnings || []) mark(w.span, 'warning', w.message);
  if (intent.venue) mark(intent.venue.span, 'venue', `venue: ${words(intent.venue.type)}`);
  for (const f of intent.world?.features || []) mark(f.span, 'world', `feature: ${countText(f.count)} × ${f.name}`);
  for (const r of intent.world?.rooms || []) mark(r.span, 'world', `room: ${r.name}`);
  for (const o of intent.world?.objects || []) mark(o.span, 'world', `object: ${o.name}`);
  for (const r of intent.robots || []) mark(r.span, 'world', `robot: ${r.words}`);
  for (const g of intent.groups || []) if (g.place) mark(g.place.span, 'place', `place of the ${g.role}s: ${g.place.phrase}`);
  (intent.exclusivity?.spans || []).forEach((s, i) => mark(s, 'only', `only the people named: '${intent.exclusivity.phrases[i] || ''}'`));
  for (const d of intent.density || []) mark(d.span, 'only', `density: ${d.word} (${d.level})`);
  for (const g of intent.groups || []) {
    mark(g.span, 'group', `${g.role}: ${countText(g.count)}`);
    mark(g.count?.span, 'count', `count: ${countText(g.count)} (${g.count.kind})`);
  }
  const out = [];
  for (let i = 0; i < text.length;) {
    let j = i + 1;
    while (j < text.length && kind[j] === kind[i] && title[j] === title[i]) j++;
    const run = text.slice(i, j);
    out.push(kind[i] ? el('mark', { class: `hl-${kind[i]}`, title: title[i], 'data-kind': kind[i] }, run) : run);
    i = j;
  }
  return out;
}

function groupItem(g) {
  const bits = [];
  if (g.activity) bits.push(g.activity);
  if (g.category) bits.push(words(g.category));
  if (g.place) bits.push(g.place.phrase);
  if (g.together) bits.push('together');
  const role = g.normalized_role && g.normalized_role !== g.role ? ` (as ${g.normalized_role})` : '';
  return el('li', { 'data-role': g.role, 'data-count': countText(g.count), 'data-kind': g.count?.kind || 'unspecified', title: g.why || '' },
    el('b', { class: 'count' }, countText(g.count)), ' ',
    el('span', { class: 'role' }, g.role), el('span', { class: 'muted' }, role),
    bits.length ? el('span', { class: 'muted' }, ` — ${bits.join(' · ')}`) : '');
}

function facts(intent) {
  const rows = [];
  if (intent.venue) {
    const laid = intent.venue.building_type && intent.venue.building_type !== intent.venue.type
      ? ` (laid out as a ${words(intent.venue.building_type)} for now)` : '';
    rows.push(['venue', `${words(intent.venue.type)}${laid}`]);
  }
  if (intent.total) rows.push(['people in all', intent.groups?.length ? countText(intent.total) : 'the generator chooses']);
  const ex = intent.exclusivity || {};
  if (ex.exclusive) rows.push(['nobody else', ex.phrases.map((p) => `'${p}'`).join(', ') || 'yes']);
  if (ex.excluded_roles?.length) rows.push(['excluded', ex.excluded_roles.join(', ')]);
  const world = [
    ...(intent.world?.features || []).map((f) => (f.count?.kind === 'unspecified' ? f.name : `${countText(f.count)} × ${f.name}`)),
    ...(intent.world?.rooms || []).map((r) => `room: ${r.name}`),
    ...(intent.world?.objects || []).map((o) => `object: ${o.name}`),
  ];
  if (world.length) rows.push(['world needs', world.join('; ')]);
  const acts = (intent.categories || []).filter((c) => c.score > 0).map((c) => words(c.category));
  rows.push(['activity', acts.length ? acts.join(', ') : 'normal operation (no activity named)']);
  if (intent.density?.length) rows.push(['density', intent.density.map((d) => `${d.word} (${d.level})`).join(', ')]);
  if (intent.background?.requested) rows.push(['others too', intent.background.words.join(', ')]);
  if (intent.robots?.length) rows.push(['robots', intent.robots.map((r) => `${countText(r.count)} × ${r.words}`).join(', ')]);
  return rows.flatMap(([k, v]) => [el('dt', {}, k), el('dd', { 'data-fact': k }, v)]);
}

// Shows an interpretation; `source` says where it comes from ("as you type", "stored with card …").
export function showIntent(intent, source) {
  $('understood-source').textContent = source;
  $('understood-problem').textContent = '';
  $('understood-prompt').replaceChildren(...highlighted(intent));
  const used = new Set([...$('understood-prompt').querySelectorAll('mark')].map((m) => m.dataset.kind));
  showLegend($('understood-legend'), KINDS.filter(([k]) => used.has(k)).map(([, name, c]) => [name, c]));
  $('understood-facts').replaceChildren(...facts(intent));
  $('understood-groups').replaceChildren(...(intent.groups || []).map(groupItem));
  $('understood-warnings').replaceChildren(...(intent.warnings || []).map((w) => el('li', {}, w.message)));
  $('understood').dataset.state = 'shown';
}

// A prompt the server refused (422: empty, not English, nothing usable …): its reason instead.
export function showIntentProblem(message, source) {
  $('understood-source').textContent = source;
  $('understood-problem').textContent = message;
  for (const id of ['understood-prompt', 'understood-legend', 'understood-facts', 'understood-groups', 'understood-warnings']) $(id).replaceChildren();
  $('understood').dataset.state = 'problem';
}

// Nothing to read yet (an empty box): a hint, not an error.
export function clearIntent(hint) {
  showIntentProblem('', hint);
  $('understood').dataset.state = 'empty';
}
