// Starts a real `socsim serve` on free 127.0.0.1 ports with a fresh SQLite file, for browser and
// API tests. The binary comes from $SOCSIM_BIN (CTest sets it).
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

function freePort() {
  return new Promise((resolve, reject) => {
    const s = createServer();
    s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => resolve(port)); });
    s.on('error', reject);
  });
}

export async function startServer(extraArgs = []) {
  const bin = process.env.SOCSIM_BIN;
  if (!bin) throw new Error('set SOCSIM_BIN to the socsim binary');
  const dir = mkdtempSync(join(tmpdir(), 'socsim-e2e-'));
  const port = await freePort();
  const wsPort = await freePort();
  const proc = spawn(bin, ['serve', '--port', String(port), '--ws-port', String(wsPort), '--db', join(dir, 'socsim.db'),
    '--web-root', join(repoRoot, 'web'), '--rate-limit', '0', ...extraArgs], { stdio: ['ignore', 'pipe', 'pipe'] });
  let log = '';
  proc.stdout.on('data', (d) => { log += d; });
  proc.stderr.on('data', (d) => { log += d; });
  const base = `http://127.0.0.1:${port}`;
  for (let i = 0; i < 100; i++) {
    try {
      const r = await fetch(`${base}/api/v1/health`);
      if (r.ok) break;
    } catch { /* not up yet */ }
    await new Promise((r) => setTimeout(r, 100));
    if (i === 99) throw new Error(`server did not start:\n${log}`);
  }
  return {
    base, port, wsPort,
    log: () => log,
    async post(path, body) {
      const r = await fetch(base + path, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
      return { status: r.status, body: await r.json() };
    },
    // Stops (SIGSTOP) or resumes (SIGCONT) the process: what it holds stays as it is meanwhile.
    freeze() { proc.kill('SIGSTOP'); },
    thaw() { proc.kill('SIGCONT'); },
    // The way a machine dies: no shutdown, no chance to hand jobs back.
    async kill9() {
      proc.kill('SIGKILL');
      await new Promise((r) => proc.once('exit', r));
    },
    async stop() {
      if (proc.exitCode !== null || proc.signalCode !== null) {
        rmSync(dir, { recursive: true, force: true });
        return;
      }
      proc.kill('SIGTERM');
      await new Promise((r) => proc.once('exit', r));
      rmSync(dir, { recursive: true, force: true });
    },
  };
}
