// Draws a socsim world (the JSON form of world.yaml: zones, walls, doors, segmentation ROIs,
// entities) on a 2D canvas, fitted to the canvas with y up. Used by the card view and, later,
// under the live agents. Plain browser JavaScript.
'use strict';

const ZONE_COLOURS = {
  corridor: '#e8e4da', lobby: '#dfe9f5', reception: '#dfe9f5', waiting_room: '#e4f1e4', waiting_area: '#e4f1e4',
  patient_room: '#f5e6e6', office: '#eef0e0', open_office: '#eef0e0', meeting_room: '#efe4f3', kitchen: '#f8efd9',
  living_room: '#e6eef6', bedroom: '#f2e8f1', bathroom: '#dff3f3', canteen: '#f8efd9', storage: '#e9e9e9',
};
const ROI_COLOURS = { queue_lane: '#d9480f', seating_area: '#2b8a3e', waiting_zone: '#1971c2', corridor: '#868e96', entrance: '#5f3dc4' };

// Returns a transform {scale, ox, oy} mapping world metres to canvas pixels for the world's bounds.
function worldTransform(world, width, height, margin = 20) {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  const grow = ([x, y]) => { minX = Math.min(minX, x); minY = Math.min(minY, y); maxX = Math.max(maxX, x); maxY = Math.max(maxY, y); };
  for (const z of world.zones || []) z.polygon.forEach(grow);
  for (const w of world.walls || []) { grow(w.start); grow(w.end); }
  if (!isFinite(minX)) return { scale: 1, ox: 0, oy: 0 };
  const scale = Math.min((width - 2 * margin) / Math.max(maxX - minX, 1e-6), (height - 2 * margin) / Math.max(maxY - minY, 1e-6));
  return { scale, ox: margin - minX * scale + (width - 2 * margin - (maxX - minX) * scale) / 2,
    oy: height - margin + minY * scale - (height - 2 * margin - (maxY - minY) * scale) / 2 };
}

function toPx(t, [x, y]) { return [t.ox + x * t.scale, t.oy - y * t.scale]; }

function drawWorld(canvas, world, opts = {}) {
  const ctx = canvas.getContext('2d');
  const t = worldTransform(world, canvas.width, canvas.height);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.font = '11px system-ui, sans-serif';
  for (const z of world.zones || []) {
    ctx.beginPath();
    z.polygon.forEach((p, i) => { const [px, py] = toPx(t, p); i ? ctx.lineTo(px, py) : ctx.moveTo(px, py); });
    ctx.closePath();
    ctx.fillStyle = ZONE_COLOURS[z.type] || '#f1f3f5';
    ctx.fill();
  }
  for (const r of world.segmentation || []) {
    ctx.beginPath();
    r.polygon.forEach((p, i) => { const [px, py] = toPx(t, p); i ? ctx.lineTo(px, py) : ctx.moveTo(px, py); });
    ctx.closePath();
    ctx.setLineDash([4, 3]);
    ctx.strokeStyle = ROI_COLOURS[r.kind] || '#495057';
    ctx.lineWidth = 1.2;
    ctx.stroke();
    ctx.setLineDash([]);
  }
  ctx.strokeStyle = '#212529';
  ctx.lineWidth = Math.max(2, 0.15 * t.scale);
  ctx.lineCap = 'round';
  for (const w of world.walls || []) {
    const [ax, ay] = toPx(t, w.start), [bx, by] = toPx(t, w.end);
    ctx.beginPath(); ctx.moveTo(ax, ay); ctx.lineTo(bx, by); ctx.stroke();
  }
  for (const d of world.doors || []) {
    const [px, py] = toPx(t, d.pose);
    ctx.fillStyle = '#f08c00';
    ctx.beginPath(); ctx.arc(px, py, Math.max(3, 0.12 * t.scale), 0, 2 * Math.PI); ctx.fill();
  }
  for (const e of world.entities || []) {
    const [px, py] = toPx(t, e.pose);
    ctx.fillStyle = '#343a40';
    ctx.fillRect(px - 3, py - 3, 6, 6);
    if (opts.labels !== false && opts.entityLabels !== false) { ctx.fillStyle = '#495057'; ctx.fillText(e.name, px + 5, py - 4); }
  }
  if (opts.labels !== false) {
    ctx.fillStyle = '#212529';
    for (const z of world.zones || []) {
      const cx = z.polygon.reduce((s, p) => s + p[0], 0) / z.polygon.length;
      const cy = z.polygon.reduce((s, p) => s + p[1], 0) / z.polygon.length;
      const [px, py] = toPx(t, [cx, cy]);
      ctx.fillText(z.name, px - ctx.measureText(z.name).width / 2, py);
    }
  }
  return t;
}

window.socsimWorld = { drawWorld, worldTransform, toPx };
