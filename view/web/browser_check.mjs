// Opens view pages in headless Chromium and checks each: no console or page errors, ready in
// time, a canvas that is not blank, and different pictures at the first and the last frame.
//
//   node view/web/browser_check.mjs [--screenshots DIR] [--browser PATH] PAGE.html…
//
// Needs Chromium (Debian: apt-get install -y chromium) and playwright-core (npm ci in view/web).
// Prints one line per page; exits non-zero naming the page and the check that failed.
import { mkdtempSync, mkdirSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { basename, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const READY_TIMEOUT_MS = 30000;
const MIN_STD = 4; // grey levels: below this the canvas is one flat colour
const MIN_CHANGED = 0.0002; // share of pixels that must differ between first and last frame

const args = process.argv.slice(2);
let screenshots = null;
let browserPath = '/usr/bin/chromium';
const pages = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--screenshots') screenshots = args[++i];
  else if (args[i] === '--browser') browserPath = args[++i];
  else pages.push(args[i]);
}
if (pages.length === 0) {
  console.error('usage: node view/web/browser_check.mjs [--screenshots DIR] [--browser PATH] PAGE.html…');
  process.exit(2);
}
if (screenshots) mkdirSync(screenshots, { recursive: true });

// In the page: copies the WebGL canvas into a 2-D canvas; keeps its pixels under `name` and
// returns the standard deviation of their grey levels.
async function snapshot(page, name) {
  return page.evaluate((key) => {
    const gl = document.querySelector('#stage canvas');
    const copy = document.createElement('canvas');
    copy.width = gl.width;
    copy.height = gl.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
    (window.__shots ??= {})[key] = data;
    let sum = 0;
    let sq = 0;
    const n = data.length / 4;
    for (let i = 0; i < data.length; i += 4) {
      const g = (data[i] + data[i + 1] + data[i + 2]) / 3;
      sum += g;
      sq += g * g;
    }
    const mean = sum / n;
    return Math.sqrt(Math.max(sq / n - mean * mean, 0));
  }, name);
}

// In the page: the share of pixels whose colour differs by more than a little between two shots.
async function changed(page, a, b) {
  return page.evaluate(([x, y]) => {
    const p = window.__shots[x];
    const q = window.__shots[y];
    let count = 0;
    for (let i = 0; i < p.length; i += 4) {
      if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 24) count++;
    }
    return count / (p.length / 4);
  }, [a, b]);
}

async function check(context, file) {
  const page = await context.newPage();
  try {
    return await checkPage(page, file);
  } finally {
    // A page left open (a failed check) would go on playing and starve the next ones.
    await page.close();
  }
}

async function checkPage(page, file) {
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  const bytes = statSync(file).size;
  const started = Date.now();
  try {
    await page.goto(pathToFileURL(resolve(file)).href, { waitUntil: 'load', timeout: READY_TIMEOUT_MS });
    await page.waitForFunction(() => window.mitStarView && (window.mitStarView.ready || window.mitStarView.error), null, { timeout: READY_TIMEOUT_MS, polling: 20 });
  } catch (e) {
    throw new Error(`not ready within ${READY_TIMEOUT_MS} ms (${e.message.split('\n')[0]}) ${errors.join('; ')}`);
  }
  const loadMs = Date.now() - started;
  const pageError = await page.evaluate(() => window.mitStarView.error);
  if (pageError) throw new Error(`the page says: ${pageError}`);
  const t = await page.evaluate(() => window.mitStarView.timings);
  const phases = t ? ` (page ready ${t.ready.toFixed(0)} ms after navigation: decode ${t.decode.toFixed(0)}, build ${t.build.toFixed(0)}, first frame ${t.firstFrame.toFixed(0)} ms)` : '';
  const frames = await page.evaluate(() => window.mitStarView.frameCount());
  await page.evaluate(() => window.mitStarView.setFrame(0));
  const std = await snapshot(page, 'first');
  if (screenshots) await page.screenshot({ path: join(screenshots, `${basename(file, '.html')}_first.png`) });
  let share = null;
  if (frames > 1) {
    // Frames within too: a motion may come back to where it began (a robot's joint sweep
    // passes its rest configuration between joints).
    share = 0;
    // Every twelfth of the way, and the middle: a joint sweep passes its rest pose often.
    const points = [...Array.from({ length: 12 }, (_, k) => [`f${k + 1}`, (k + 1) / 12]), ['middle', 0.5]];
    for (const [name, at] of points.map(([n, f]) => (f === 1 ? ['last', 1] : [n, f]))) {
      await page.evaluate(([n, f]) => window.mitStarView.setFrame(Math.round((n - 1) * f)), [frames, at]);
      await snapshot(page, name);
      if (screenshots && (name === 'middle' || name === 'last')) await page.screenshot({ path: join(screenshots, `${basename(file, '.html')}_${name}.png`) });
      share = Math.max(share, await changed(page, 'first', name));
    }
    if (screenshots) await page.screenshot({ path: join(screenshots, `${basename(file, '.html')}_last.png`) });
  }
  // Each toggle changes the picture; play moves the slider. The mesh toggle is held to it
  // only where meshes stand for most of the robot (a robot with one small visual primitive
  // and its other meshes missing looks the same either way).
  const mostlyMeshes = await page.evaluate(() => {
    const robot = JSON.parse(document.getElementById('mit-star-view-data').textContent).robot;
    if (!robot) return false;
    const withSpheres = robot.links.filter((l) => l.spheres.length > 0);
    return 2 * withSpheres.filter((l) => l.meshes.length > 0).length >= withSpheres.length;
  });
  const toggled = [];
  for (const id of ['mesh-toggle', 'ghost-toggle', 'search-toggle']) {
    const box = await page.$(`#${id}:not([disabled])`);
    if (!box || (id === 'mesh-toggle' && !mostlyMeshes)) continue;
    await page.evaluate(() => window.mitStarView.setFrame(0));
    await snapshot(page, 'before');
    await box.click();
    await page.evaluate(() => window.mitStarView.render());
    await snapshot(page, 'after');
    const share = await changed(page, 'before', 'after');
    if (screenshots) await page.screenshot({ path: join(screenshots, `${basename(file, '.html')}_${id}.png`) });
    await box.click();
    if (!(share > MIN_CHANGED)) errors.push(`toggling #${id} changes ${(100 * share).toFixed(3)} % of pixels`);
    toggled.push(`${id.replace('-toggle', '')} ${(100 * share).toFixed(3)} %`);
  }
  if (frames > 1) {
    await page.evaluate(() => window.mitStarView.setFrame(0));
    // The button's own click handler, run in the page: Playwright's click would wait for the
    // button to be stable across animation frames, slow while software WebGL draws a heavy robot.
    await page.evaluate(() => document.getElementById('play').click());
    // Playback advances by the frames drawn: slow under software WebGL, so wait for it.
    const moved = await page
      .waitForFunction(() => window.mitStarView.frame() > 0, null, { timeout: 10000, polling: 50 })
      .then(() => true, () => false);
    // Stop through the page (setFrame stops playback): a second click on a busy page waits.
    await page.evaluate(() => window.mitStarView.setFrame(0));
    if (!moved) errors.push('play does not move the motion within 10 s');
  }
  const motions = await page.evaluate(() => window.mitStarView.motionCount());
  for (let k = 1; k < motions; k++) await page.evaluate((m) => window.mitStarView.setMotion(m), k);
  const line = `${file}: load ${loadMs} ms${phases}, ${bytes} bytes, ${frames} frames, ${motions} motions, pixel std ${std.toFixed(1)}, changed first→others ${share === null ? '-' : (100 * share).toFixed(2) + ' %'}, toggles checked: ${toggled.join(', ') || '-'}`;
  if (errors.length > 0) throw new Error(`${errors.length} errors: ${errors.slice(0, 5).join(' | ')}\n  ${line}`);
  if (!(std > MIN_STD)) throw new Error(`blank canvas: pixel std ${std.toFixed(2)} ≤ ${MIN_STD}\n  ${line}`);
  if (share !== null && !(share > MIN_CHANGED)) throw new Error(`every twelfth of the motion looks like its first frame: ${(100 * share).toFixed(3)} % of pixels changed ≤ ${100 * MIN_CHANGED} %\n  ${line}`);
  return line;
}

const profile = mkdtempSync(join(tmpdir(), 'mit-star-view-check-'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: browserPath,
  headless: true,
  viewport: { width: 1280, height: 800 },
  args: [
    '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    // Software WebGL: ANGLE on SwiftShader, which headless Chromium otherwise refuses.
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  ],
});
let failures = 0;
try {
  for (const file of pages) {
    try {
      console.log(await check(context, file));
    } catch (e) {
      failures++;
      console.error(`FAIL ${file}: ${e.message}`);
    }
  }
} finally {
  await context.close();
  rmSync(profile, { recursive: true, force: true });
}
console.log(`${pages.length - failures} passed, ${failures} failed`);
process.exit(failures > 0 ? 1 : 0);
