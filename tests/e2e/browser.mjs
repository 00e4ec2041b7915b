// Headless Debian Chromium for the viewer tests (playwright-core drives the system browser; nothing
// is downloaded). `browserSkip` is the reason to skip when the browser is not installed.
import { existsSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { repoRoot } from './server.mjs';

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
