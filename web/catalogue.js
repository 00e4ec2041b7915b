// socsim catalogue viewer: browse, search and open scenario cards; new cards appear live
// through the WebSocket named by GET /api/v1/info. Plain ES module, no build step.
import { $, api, el, getJson, toast, serverInfo, setLive, drawPlan } from './common.js';

// `listing` counts listings (first pages): a page that arrives after a newer listing began (a search
// submitted while the first page loads) is dropped instead of being appended to the new list.
const state = { cursor: null, selected: null, query: {}, listing: 0 };

function cardItem(card, fresh = false) {
  const tags = el('div', { class: 'tags' }, ...card.tags.map((t) => el('span', {}, t)));
  const li = el('li', { 'data-id': card.id, class: fresh ? 'fresh' : '', onclick: () => openCard(card.id) },
    el('div', { class: 'title' }, card.title),
    el('div', { class: 'muted' }, `${card.domain || 'no domain'} · v${card.version} · ${card.author} · ${card.created_at.slice(0, 16).replace('T', ' ')}`),
    tags);
  if (card.id === state.selected) li.classList.add('selected');
  return li;
}

function listUrl() {
  const p = new URLSearchParams({ page_size: '20' });
  for (const [k, v] of Object.entries(state.query)) if (v) p.set(k, v);
  if (state.cursor) p.set('cursor', state.cursor);
  return `/cards?${p}`;
}

async function loadPage(reset) {
  if (reset) { state.cursor = null; $('cards').replaceChildren(); }
  const listing = reset ? ++state.listing : state.listing;
  try {
    const page = await getJson(listUrl());
    if (listing !== state.listing) return;  // superseded
    for (const c of page.items) $('cards').append(cardItem(c));
    state.cursor = page.next_cursor;
    $('more').hidden = !page.next_cursor;
    $('empty').hidden = $('cards').children.length > 0;
  } catch (e) {
    if (listing === state.listing) toast(`Could not list cards: ${e.message}`);
  }
}

async function openCard(id) {
  state.selected = id;
  history.replaceState(null, '', `#card=${id}`);
  for (const li of $('cards').children) li.classList.toggle('selected', li.dataset.id === id);
  const d = $('detail');
  try {
    const c = await getJson(`/cards/${encodeURIComponent(id)}`);
    const rows = [['prompt', c.prompt || '—'], ['domain', c.domain || '—'], ['seed', c.seed],
      ['generator', c.generator.model ? `${c.generator.name} (${c.generator.model})` : c.generator.name],
      ['author', c.author], ['version', c.version], ['created', c.created_at], ['content hash', c.content_hash]];
    const dl = el('dl');
    for (const [k, v] of rows) dl.append(el('dt', {}, k), el('dd', {}, v));
    if (c.parent_id) dl.append(el('dt', {}, 'parent'), el('dd', {}, el('a', { href: `#card=${c.parent_id}`, onclick: () => openCard(c.parent_id) }, c.parent_id)));
    d.replaceChildren(
      el('h2', {}, c.title),
      el('p', {}, c.description || ''),
      el('div', { class: 'tags' }, ...c.tags.map((t) => el('span', {}, t))),
      dl,
      c.trajectory_log ? el('p', {}, el('a', { href: `./#card=${c.id}`, class: 'watch' }, '▶ Watch the scenario')) : '',
      el('p', {}, el('a', { href: `${api}/cards/${c.id}/export`, download: `${c.id}.card.json` }, 'Download export file'),
        ' · ', el('a', { href: `#card=${c.id}`, onclick: () => { navigator.clipboard?.writeText(location.href); toast('Link copied'); } }, 'Share link')),
      el('h3', {}, 'Metrics'), el('pre', {}, JSON.stringify(c.metrics, null, 2)),
      el('h3', {}, 'World'),
      (c.world && Array.isArray(c.world.zones) && c.world.zones.length)
        ? worldCanvas(c.world) : el('p', { class: 'muted' }, 'No world drawn for this card.'),
      el('details', {}, el('summary', {}, 'world JSON'), el('pre', {}, JSON.stringify(c.world, null, 2))),
      el('h3', {}, 'Program'), el('pre', {}, JSON.stringify(c.program, null, 2)));
  } catch (e) {
    d.replaceChildren(el('p', {}, `Could not open ${id}: ${e.message}`));
  }
}

function worldCanvas(world) {
  const canvas = el('canvas', { width: '720', height: '420', class: 'plan world', 'aria-label': `floor plan ${world.name || ''}` });
  drawPlan(canvas, world);
  return canvas;
}

function connectLive(url) {
  const ws = new WebSocket(url.replace(/\/ws$/, '/ws/catalogue'));
  ws.onopen = () => setLive(true);
  ws.onclose = () => { setLive(false); setTimeout(() => connectLive(url), 3000); };
  ws.onmessage = (m) => {
    const ev = JSON.parse(m.data);
    if (ev.type === 'card.created' && !Object.values(state.query).some(Boolean)) {
      $('cards').prepend(cardItem(ev.card, true));
      $('empty').hidden = true;
      toast(`New card: ${ev.card.title}`);
    } else if (ev.type === 'card.deleted') {
      document.querySelector(`#cards li[data-id="${ev.card.id}"]`)?.remove();
    }
  };
}

async function main() {
  $('search').addEventListener('submit', (e) => {
    e.preventDefault();
    state.query = { q: $('q').value.trim(), tag: $('tag').value.trim(), domain: $('domain').value };
    loadPage(true);
  });
  $('more').addEventListener('click', () => loadPage(false));
  setLive(false);
  serverInfo.then((info) => connectLive(info.websocket_url), () => {});  // the header says when the server is not reachable
  await loadPage(true);
  const m = location.hash.match(/card=(crd_[0-9a-z]+)/);
  if (m) openCard(m[1]);
}

main();
