// The web build as a school installs and uses it: served, the page is an installable app that
// opens with no network and takes a new build when the folder is updated; a panic is shown
// over the page, never a frozen picture; inside another page it offers a tab of its own.
// Run after `cargo xtask web` (`.ci/run` does both): `npm test` in this folder.

import assert from 'node:assert/strict';
import { test } from 'node:test';

import {
  W_COLOUR, close, colours, decodePng, launch, newPage, open, pixels, placesOf, ready, said, serve,
} from './browser.mjs';

/** A state beyond the critical angle: glass to air at 53°, as `--state` reads it. */
const BEYOND_CRITICAL = '{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}';

/** The prefix of the service worker's caches (web_page::CACHE_PREFIX). */
const CACHE_PREFIX = 'refraction-explorer-';

/** The fragment that panics a build with debug assertions (web_page::DEBUG_PANIC_FRAGMENT). */
const DEBUG_PANIC = 'debug-panic-on-purpose';

/** Runs `check` with a browser of a fresh profile and a server of its own (`changed` as serve's). */
async function served(check, changed = null) {
  const { server, base } = await serve(changed);
  const context = await launch();
  try {
    await check(context, base, server);
  } finally {
    await close(context);
    server.close();
  }
}

/** The names of the page's service worker caches, each with how many files it holds. */
async function caches(page) {
  return page.evaluate(async (prefix) => {
    const names = (await globalThis.caches.keys()).filter((name) => name.startsWith(prefix));
    return Promise.all(names.map(async (name) => {
      const cache = await globalThis.caches.open(name);
      return { name, files: (await cache.keys()).length };
    }));
  }, CACHE_PREFIX);
}

/** Waits until the page's service worker controls it and its cache holds the whole build. */
async function installed(page) {
  await page.evaluate(() => navigator.serviceWorker.ready);
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: 30_000 });
  for (let tries = 0; tries < 100; tries++) {
    const kept = await caches(page);
    if (kept.length === 1 && kept[0].files >= 7) return kept[0];
    await page.waitForTimeout(200);
  }
  throw new Error(`the build is not cached: ${JSON.stringify(await caches(page))}`);
}

test('served, the page links a manifest an installing browser accepts', async () => {
  await served(async (context, base) => {
    const page = await newPage(context);
    await open(page, base);
    const href = await page.getAttribute('link[rel="manifest"]', 'href');
    const manifest = await (await fetch(new URL(href, base))).json();
    assert.equal(manifest.name, 'Refraction explorer');
    assert.equal(manifest.display, 'standalone');
    assert.equal(new URL(manifest.start_url, new URL(href, base)).href, base, 'starts at the folder');
    const sizes = [];
    for (const icon of manifest.icons) {
      const png = Buffer.from(await (await fetch(new URL(icon.src, base))).arrayBuffer());
      const picture = decodePng(png);
      assert.equal(`${picture.width}x${picture.height}`, icon.sizes, icon.src);
      assert.equal(icon.type, 'image/png');
      sizes.push(picture.width);
    }
    assert.ok(sizes.includes(192) && sizes.includes(512), `icons of 192 and 512 pixels: ${sizes}`);
    assert.deepEqual(page.errors, [], 'no console error');
  });
});

test('after one visit the page loads and draws with the network off', async () => {
  await served(async (context, base, server) => {
    const page = await newPage(context);
    await open(page, `${base}#state=${encodeURIComponent(BEYOND_CRITICAL)}`);
    const worker = await page.evaluate(async () => (await navigator.serviceWorker.ready).active.scriptURL);
    assert.equal(worker, `${base}service-worker.js`);
    const cache = await installed(page);
    assert.match(cache.name, /^refraction-explorer-[0-9a-f]{16}$/, 'named after the build');
    // The network off: the browser offline and the server gone.
    await context.setOffline(true);
    server.close();
    server.closeAllConnections();
    await page.reload();
    await ready(page);
    const picture = await pixels(page);
    assert.ok(colours(picture) > 40, 'drawn');
    // Under total internal reflection W past the surface is dotted: its handle and dots.
    const w = placesOf(picture, W_COLOUR).length;
    assert.ok(w > 50, `W is drawn (${w} pixels of its colour)`);
    assert.match(await said(page), /TOTAL INTERNAL REFLECTION/, 'the link opens offline too');
    assert.deepEqual(page.errors, [], 'no console error');
  });
});

test('an updated folder replaces the cached build at the next visit', async () => {
  let update = false;
  // The update: another build's service worker (its cache named after that build).
  const changed = (name, text) => (update && name === 'service-worker.js'
    ? text().replace(/refraction-explorer-[0-9a-f]{16}/, 'refraction-explorer-0000000000000002')
    : null);
  await served(async (context, base) => {
    const page = await newPage(context);
    await open(page, base);
    const first = await installed(page);
    update = true;
    await page.reload();
    await ready(page);
    for (let tries = 0; tries < 100; tries++) {
      const kept = await caches(page);
      if (kept.length === 1 && kept[0].name !== first.name && kept[0].files >= 7) break;
      await page.waitForTimeout(200);
    }
    const kept = await caches(page);
    assert.deepEqual(kept.map((c) => c.name), ['refraction-explorer-0000000000000002'], 'the old build\'s cache is gone');
    assert.ok(kept[0].files >= first.files, 'the new cache holds the whole build');
    assert.deepEqual(page.errors, [], 'no console error');
  }, changed);
});

test('a panic is shown over the page with its message, a reload and the last state\'s link', async () => {
  await served(async (context, base) => {
    const page = await newPage(context);
    await open(page, `${base}#state=${encodeURIComponent(BEYOND_CRITICAL)}`);
    const debug = await page.evaluate(() => document.documentElement.hasAttribute('data-debug-assertions'));
    await page.evaluate((fragment) => { location.hash = `#${fragment}`; }, DEBUG_PANIC);
    if (!debug) {
      // A release build has no way to panic on purpose: the fragment is a link it does not read.
      await page.waitForFunction(() => /could not be opened/.test(document.getElementById('status')?.textContent ?? ''));
      assert.ok(await page.isHidden('#crashed'), 'no overlay');
      assert.match(await said(page), /TOTAL INTERNAL REFLECTION/, 'the state stays');
      return;
    }
    await page.waitForSelector('#crashed', { state: 'visible', timeout: 10_000 });
    const shown = await page.textContent('#crashed');
    assert.match(shown, /The explorer stopped/, shown);
    assert.match(shown, /panicked on purpose/, 'the panic\'s own message');
    assert.ok(page.errors.some((e) => /panicked on purpose/.test(e)), 'and in the console');
    const reload = await page.getAttribute('#crashed a.reload', 'href');
    assert.equal(reload, `${base}#${DEBUG_PANIC}`, 'reload: the page as it is');
    const reopen = await page.getAttribute('#crashed a.reopen', 'href');
    assert.ok(reopen.startsWith(`${base}#state=`), reopen);
    // The overlay covers the frozen canvas, readable: what it says is at its middle.
    const middle = await page.evaluate(() => {
      const element = document.elementFromPoint(innerWidth / 2, innerHeight / 2);
      return element.closest('#crashed') !== null;
    });
    assert.ok(middle, 'the overlay is over the canvas');
    // The last state's link brings the work back.
    await page.click('#crashed a.reopen');
    await ready(page);
    assert.match(await said(page), /TOTAL INTERNAL REFLECTION/);
    assert.ok(await page.isHidden('#crashed'));
  });
});

test('a dropped file too large for the page is refused before it is read, and said', async () => {
  await served(async (context, base) => {
    const page = await newPage(context);
    await open(page, base);
    await page.evaluate(() => {
      const file = new File([new Uint8Array(17 * 1024 * 1024)], 'huge.log');
      const data = new DataTransfer();
      data.items.add(file);
      const canvas = document.getElementById('explorer');
      for (const type of ['dragenter', 'dragover', 'drop']) {
        canvas.dispatchEvent(new DragEvent(type, { dataTransfer: data, bubbles: true, cancelable: true }));
      }
    });
    await page.waitForFunction(() => /huge\.log is 17\.0 MB/.test(document.getElementById('status')?.textContent ?? ''));
    const words = await page.textContent('#status');
    assert.match(words, /at most 16 MB/, words);
    assert.deepEqual(page.errors, [], 'no console error');
  });
});

test('inside another page, a link opens the explorer in a tab of its own at the same state', async () => {
  await served(async (context, base) => {
    const page = await newPage(context);
    await open(page, base);
    assert.ok(await page.isHidden('#new-tab'), 'not offered in a tab of its own');
    const link = `${base}#state=${encodeURIComponent(BEYOND_CRITICAL)}`;
    await page.setContent(`<iframe src="${link}" allow="fullscreen; clipboard-write" style="width:900px;height:600px"></iframe>`);
    const frame = page.frames()[1];
    await frame.waitForFunction(() => document.getElementById('explorer')?.getAttribute('aria-label'), null, { timeout: 60_000 });
    await frame.waitForSelector('#new-tab', { state: 'visible' });
    assert.match(await frame.textContent('#new-tab'), /Open in a new tab/);
    const [tab] = await Promise.all([context.waitForEvent('page'), frame.click('#new-tab')]);
    await tab.waitForLoadState();
    await ready(tab);
    assert.match(tab.url(), /#state=/);
    assert.match(await said(tab), /TOTAL INTERNAL REFLECTION/);
    assert.ok(await tab.isHidden('#new-tab'), 'the tab of its own offers no other');
  });
});
