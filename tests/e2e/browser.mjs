// Headless Debian Chromium for the viewer tests (playwright-core drives the system browser; nothing
// is downloaded). `browserSkip` is the reason to skip when the browser is not installed.
import { existsSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { before, after } from 'node:test';
import { repoRoot, startServer } from './server.mjs';

export const chromiumPath = '/usr/bin/chromium';
export const artifacts = join(repoRoot, 'tests', 'e2e', 'artifacts');
export const browserSkip = !existsSync(chromiumPath) &&
  'Debian chromium is not installed (bash deploy/install-deps.sh --with-browser)';

export async function launchBrowser() {
  const { chromium } = await import('playwright-core');
  mkdirSync(artifacts, { recursive: true });
  return chromium.launch({
    executablePath: chromiumPath,
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run', '--disable-quic'],
  });
}

// One daemon and one browser for a test file, started before its tests and stopped after them:
// `const suite = browserSuite();`, then `suite.server` and `suite.browser` inside the tests.
export function browserSuite(serverArgs = []) {
  const suite = { server: undefined, browser: undefined };
  before(async () => {
    if (browserSkip) return;
    suite.server = await startServer(serverArgs);
    suite.browser = await launchBrowser();
  });
  after(async () => {
    await suite.browser?.close();
    await suite.server?.stop();
  });
  return suite;
}

// The share of a canvas's pixels that something was drawn on (alpha > 0).
export function inkedFraction(page, selector) {
  return page.evaluate((sel) => {
    const c = document.querySelector(sel);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
    return n / (c.width * c.height);
  }, selector);
}
