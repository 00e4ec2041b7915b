// Real API outputs checked against the published JSON Schemas with ajv (a second, independent
// validator), and every schema in schemas/ compiled by it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import Ajv2020 from 'ajv/dist/2020.js';
import { startServer, repoRoot } from './server.mjs';

const schemaDir = join(repoRoot, 'schemas');
let server;
before(async () => { server = await startServer(); });
after(async () => { await server?.stop(); });

function ajv() {
  const a = new Ajv2020({ strict: false, allErrors: true });
  for (const f of readdirSync(schemaDir).filter((n) => n.endsWith('.schema.json'))) {
    const s = JSON.parse(readFileSync(join(schemaDir, f), 'utf8'));
    a.addSchema(s, f);
  }
  return a;
}

test('every schema in schemas/ compiles', () => {
  const a = ajv();
  for (const f of readdirSync(schemaDir).filter((n) => n.endsWith('.schema.json'))) {
    assert.ok(a.getSchema(f), `${f} did not compile`);
  }
});

test('created, listed and exported cards match card.schema.json', async () => {
  const a = ajv();
  const validate = a.getSchema('card.schema.json');
  const input = { title: 'Bottleneck', prompt: 'the crowd squeezes through one door', tags: ['bottleneck'], seed: 3,
    generator: { name: 'offline' }, domain: 'office', metrics: { flow: 1.3 } };
  const inputOk = a.compile({ $ref: 'card.schema.json#/$defs/CardContent' })(input);
  assert.ok(inputOk, 'the example POST body must match CardContent');
  const created = await server.post('/api/v1/cards', input);
  assert.equal(created.status, 201);
  assert.ok(validate(created.body), JSON.stringify(validate.errors));
  const exported = await (await fetch(`${server.base}/api/v1/cards/${created.body.id}/export`)).json();
  assert.ok(validate(exported.card), JSON.stringify(validate.errors));
  const problem = await server.post('/api/v1/cards', { title: 7 });
  assert.equal(problem.status, 422);
  assert.deepEqual(problem.body.errors.map((e) => e.pointer), ['/title']);
});

test('POST /api/v1/scenarios/interpret answers match intent.schema.json; refusals are problems at /prompt', async () => {
  const validate = ajv().getSchema('intent.schema.json');
  for (const prompt of ['A library that is empty except for 3 librarians shelving books',
    'Fire alarm in the hospital: about two hundred people leave through the two exits',
    'Between 20 and 30 commuters squeeze through the narrow ticket gate of the train station',
    'In the café, 20 customers wait']) {
    const r = await server.post('/api/v1/scenarios/interpret', { prompt });
    assert.equal(r.status, 200, JSON.stringify(r.body));
    assert.ok(validate(r.body), `${prompt}: ${JSON.stringify(validate.errors)}`);
    assert.equal(r.body.prompt, prompt);
  }
  for (const prompt of ['', '   ', 'Zwanzig Patienten warten im Wartezimmer auf den Arzt', 'hello there']) {
    const r = await server.post('/api/v1/scenarios/interpret', { prompt });
    assert.equal(r.status, 422, prompt);
    assert.deepEqual(r.body.errors.map((e) => e.pointer), ['/prompt'], prompt);
  }
});
