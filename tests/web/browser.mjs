// What the browser tests and the measurements share: Debian's Chromium started headless
// through playwright-core, a static server for target/web on the loopback address, and ways
// to read the explorer's page (its canvas's accessible name, its pixels).

import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import zlib from 'node:zlib';
import { chromium } from 'playwright-core';

/** The folder `cargo xtask web` wrote. */
export const WEB = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../target/web');

/** The flags the project starts Chromium with (see the README's "In a browser"). */
const FLAGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--enable-unsafe-swiftshader',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript',
  '.wasm': 'application/wasm',
  '.webmanifest': 'application/manifest+json',
  '.png': 'image/png',
};

/**
 * Serves WEB on 127.0.0.1 at a free port; resolves to the server and its address.
 * `changed(name, text)`, if given, may give another text for a file (an update of the folder).
 */
export async function serve(changed = null) {
  const server = http.createServer((request, response) => {
    const name = decodeURIComponent(new URL(request.url, 'http://x').pathname);
    const file = path.join(WEB, name === '/' ? 'index.html' : name);
    if (!file.startsWith(WEB) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { 'content-type': TYPES[path.extname(file)] || 'application/octet-stream' });
    const text = changed?.(path.basename(file), () => fs.readFileSync(file, 'utf8'));
    if (text != null) response.end(text);
    else fs.createReadStream(file).pipe(response);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { server, base: `http://127.0.0.1:${server.address().port}/` };
}

/**
 * Debian's Chromium, headless, with a fresh profile; resolves to a browser context. `device`
 * adds to the context's options (`{ hasTouch: true, isMobile: true }` for a phone), `extra`
 * to Chromium's flags.
 */
export async function launch(size = { width: 1280, height: 720 }, locale = 'en-US', device = {}, extra = []) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'refraction-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: [...FLAGS, ...extra],
    viewport: size,
    deviceScaleFactor: 1,
    locale,
    acceptDownloads: true,
    ...device,
  });
  context.profile = profile;
  return context;
}

/** Closes the context and removes its profile. */
export async function close(context) {
  await context.close();
  fs.rmSync(context.profile, { recursive: true, force: true });
}

/**
 * Runs `check(page, context)` on a new page of a browser with a fresh profile (nothing kept
 * from another test), speaking `locale`, started with the `extra` flags; fails on any console
 * error.
 */
export async function inBrowser(check, locale = 'en-US', extra = []) {
  const context = await launch(undefined, locale, {}, extra);
  try {
    const page = await newPage(context);
    await check(page, context);
    assert.deepEqual(page.errors, [], 'no console error');
  } finally {
    await close(context);
  }
}

/** A new page that keeps every console error and uncaught exception in `page.errors`. */
export async function newPage(context) {
  const page = await context.newPage();
  page.errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') page.errors.push(message.text());
  });
  page.on('pageerror', (error) => page.errors.push(String(error)));
  return page;
}

/** Opens `url` and waits for the explorer to run: the loading line gone, the canvas named. */
export async function open(page, url) {
  await page.goto(url);
  await ready(page);
}

/** Waits for the explorer to run and draw. */
export async function ready(page) {
  await page.waitForFunction(
    () => !document.getElementById('loading') && document.getElementById('explorer').getAttribute('aria-label'),
    null,
    { timeout: 60_000 },
  );
  await frames(page, 3);
}

/** Waits for `count` animation frames of the page. */
export async function frames(page, count) {
  await page.evaluate(
    (n) => new Promise((resolve) => {
      const step = (left) => (left === 0 ? resolve() : requestAnimationFrame(() => step(left - 1)));
      step(n);
    }),
    count,
  );
}

/** What the canvas says to screen readers: the diagram's banner in words. */
export async function said(page) {
  return page.getAttribute('#explorer', 'aria-label');
}

/** The pixels of a PNG that Chromium wrote (8-bit RGB or RGBA, not interlaced): { width, height, data } (RGBA). */
export function decodePng(png) {
  let at = 8;
  let width = 0;
  let height = 0;
  let channels = 4;
  const compressed = [];
  while (at < png.length) {
    const length = png.readUInt32BE(at);
    const type = png.toString('ascii', at + 4, at + 8);
    const body = png.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      if (body[8] !== 8 || body[12] !== 0) throw new Error('an 8-bit, non-interlaced PNG is expected');
      channels = { 2: 3, 6: 4 }[body[9]];
    } else if (type === 'IDAT') {
      compressed.push(body);
    }
    at += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(compressed));
  const stride = width * channels;
  const rows = Buffer.alloc(stride * height);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const left = x >= channels ? rows[y * stride + x - channels] : 0;
      const up = y > 0 ? rows[(y - 1) * stride + x] : 0;
      const corner = y > 0 && x >= channels ? rows[(y - 1) * stride + x - channels] : 0;
      const paeth = () => {
        const p = left + up - corner;
        const [a, b, c] = [Math.abs(p - left), Math.abs(p - up), Math.abs(p - corner)];
        return a <= b && a <= c ? left : b <= c ? up : corner;
      };
      const predicted = [0, left, up, (left + up) >> 1, paeth()][filter];
      rows[y * stride + x] = (line[x] + predicted) & 0xff;
    }
  }
  const data = new Uint8Array(width * height * 4);
  for (let i = 0, j = 0; i < width * height; i++, j += channels) {
    data.set(rows.subarray(j, j + 3), 4 * i);
    data[4 * i + 3] = channels === 4 ? rows[j + 3] : 255;
  }
  return { width, height, data };
}

/** The page as the screen shows it: { width, height, data } (RGBA bytes). */
export async function pixels(page) {
  return decodePng(await page.screenshot());
}

/** The places whose colour is `rgb` (each channel within `tolerance`). */
export function placesOf(picture, [r, g, b], tolerance = 6) {
  const found = [];
  const { width, height, data } = picture;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      const near = Math.abs(data[i] - r) <= tolerance
        && Math.abs(data[i + 1] - g) <= tolerance
        && Math.abs(data[i + 2] - b) <= tolerance;
      if (near) found.push({ x, y });
    }
  }
  return found;
}

/** How many different colours the picture has (counted to 256 at most). */
export function colours(picture) {
  const seen = new Set();
  for (let i = 0; i < picture.data.length && seen.size < 256; i += 4) {
    seen.add((picture.data[i] << 16) | (picture.data[i + 1] << 8) | picture.data[i + 2]);
  }
  return seen.size;
}

/** W's colour in the standard palette (refraction_diagram::palette::W, #E69F00). */
export const W_COLOUR = [0xe6, 0x9f, 0x00];

/**
 * Where W's handle can be grabbed: a place in W's colour where the pointer turns into the
 * grabbing hand (the canvas's cursor is `grab` over a handle). Tried from the W-coloured
 * places farthest from the diagram's middle (the handle is at W's tip).
 */
export async function wHandle(page) {
  const picture = await pixels(page);
  const places = placesOf(picture, W_COLOUR);
  if (places.length === 0) throw new Error('no pixel in W\'s colour');
  const middle = { x: picture.width / 2, y: picture.height / 2 };
  const far = (p) => -Math.hypot(p.x - middle.x, p.y - middle.y);
  places.sort((a, b) => far(a) - far(b));
  for (const place of places.filter((_, i) => i % 7 === 0).slice(0, 80)) {
    await page.mouse.move(place.x, place.y);
    await frames(page, 2);
    const cursor = await page.evaluate(() => document.getElementById('explorer').style.cursor);
    if (cursor === 'grab') return place;
  }
  throw new Error(`no place in W's colour grabs (${places.length} tried at most 80)`);
}

/** Drags from `from` by (`dx`, `dy`) in `steps` moves, a frame after each. */
export async function drag(page, from, dx, dy, steps = 20) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    await page.mouse.move(from.x + (dx * i) / steps, from.y + (dy * i) / steps);
    await frames(page, 1);
  }
  await page.mouse.up();
  await frames(page, 3);
}

/** What the page's live region says (the window's strip, for screen readers). */
export async function status(page) {
  return page.evaluate(() => document.getElementById('status')?.textContent ?? '');
}

/**
 * Opens `url` in `page`; resolves to when the first animation frame after the explorer named
 * its canvas (which it does at the end of its first frame) came, in ms since the page started.
 */
export async function firstFrameAt(page, url) {
  await page.addInitScript(() => {
    window.firstFrame = new Promise((resolve) => {
      const watch = () => {
        const canvas = document.getElementById('explorer');
        if (canvas && canvas.getAttribute('aria-label')) {
          requestAnimationFrame(() => resolve(performance.now()));
        } else {
          requestAnimationFrame(watch);
        }
      };
      requestAnimationFrame(watch);
    });
  });
  await page.goto(url);
  return page.evaluate(() => window.firstFrame);
}

/**
 * Starts keeping the window's own time for each frame (its `explorer-frame` performance
 * measures, see app::browser::page::report_frame) in `window.frameTimes`, in ms.
 */
export async function recordFrameTimes(page) {
  await page.evaluate(() => {
    window.frameTimes = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) {
        if (entry.name === 'explorer-frame') window.frameTimes.push(entry.duration);
      }
    }).observe({ type: 'measure' });
  });
}

/** How long the page's main thread has been busy so far (Chromium's TaskDuration), in ms. */
export async function mainThreadMs(cdp) {
  const { metrics } = await cdp.send('Performance.getMetrics');
  return metrics.find((m) => m.name === 'TaskDuration').value * 1000;
}
