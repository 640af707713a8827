// A small test runner over playwright-core: builds the page, serves the static build with
// `vite preview` on a free port, runs every registered test in a fresh browser context against
// Debian's Chromium (never a downloaded browser), prints `N passed, N failed` and sets the exit code.
import { mkdirSync } from 'node:fs';
import { createServer } from 'node:net';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { build, preview } from 'vite';

export const ROOT = fileURLToPath(new URL('../..', import.meta.url));
export const RESULTS = `${ROOT}test-results/browser`;
const CHROMIUM = process.env.TESSERA_CHROMIUM ?? '/usr/bin/chromium';
const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-quic',
  '--no-first-run',
  '--disable-component-update',
  '--disable-sync',
];
const TEST_TIMEOUT_MS = 90_000;

const tests = [];

/** Registers a test: fn({ page, url, context }) runs in its own browser context. */
export function test(name, fn) {
  tests.push({ name, fn });
}

function freePort() {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

/** Builds the page and serves it with `vite preview` on a free port: { server, url }. */
export async function servePage() {
  await build({ root: `${ROOT}web`, configFile: `${ROOT}vite.config.js`, logLevel: 'warn' });
  const port = await freePort();
  const server = await preview({
    configFile: `${ROOT}vite.config.js`,
    preview: { port, strictPort: true, host: '127.0.0.1' },
    logLevel: 'warn',
  });
  return { server, url: `http://127.0.0.1:${port}/` };
}

/** Debian's Chromium, headless. */
export function launchBrowser() {
  return chromium.launch({ executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS });
}

function withTimeout(promise, ms, what) {
  let timer;
  const timeout = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} took longer than ${ms / 1000} s`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

async function runOne(browser, url, { name, fn }) {
  // The static build's service worker would answer requests that a test routes (a core that cannot
  // be loaded): blocked here, allowed in the offline test's own context.
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, acceptDownloads: true, serviceWorkers: 'block' });
  const page = await context.newPage();
  const pageErrors = [];
  page.on('pageerror', (error) => pageErrors.push(error.message));
  page.on('console', (message) => {
    if (message.type() === 'error') pageErrors.push(`console: ${message.text()}`);
  });
  try {
    await withTimeout(fn({ page, url, context }), TEST_TIMEOUT_MS, name);
    if (pageErrors.length > 0) throw new Error(`errors in the page:\n  ${pageErrors.join('\n  ')}`);
  } catch (error) {
    const shot = `${RESULTS}/failed-${name.replace(/[^a-z0-9]+/gi, '-')}.png`;
    await page.screenshot({ path: shot }).catch(() => {});
    throw error;
  } finally {
    await context.close();
  }
}

/** Runs the registered tests whose names contain `filter` (all when empty). */
export async function runTests(filter = '') {
  mkdirSync(RESULTS, { recursive: true });
  const selected = tests.filter(({ name }) => name.includes(filter));
  let passed = 0;
  let failed = 0;
  const { server, url } = await servePage();
  const browser = await launchBrowser();
  try {
    for (const entry of selected) {
      const started = Date.now();
      try {
        await runOne(browser, url, entry);
        passed++;
        console.log(`ok   ${entry.name} (${Date.now() - started} ms)`);
      } catch (error) {
        failed++;
        console.log(`FAIL ${entry.name} (${Date.now() - started} ms)\n     ${error.stack ?? error}`);
      }
    }
  } finally {
    await browser.close();
    await new Promise((resolve) => server.httpServer.close(resolve));
  }
  console.log(`browser: ${passed} passed, ${failed} failed`);
  return failed === 0 && passed > 0;
}
