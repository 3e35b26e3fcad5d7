// The web build in a real browser: Debian's Chromium, headless, driven through playwright-core.
// Run after `cargo xtask web` (`.ci/run` does both): `npm test` in this folder.

import assert from 'node:assert/strict';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { pathToFileURL } from 'node:url';

import {
  WEB, W_COLOUR, colours, drag, frames, inBrowser, open, pixels, placesOf, ready, said, serve,
  status, wHandle,
} from './browser.mjs';

let server;
let base;

before(async () => {
  ({ server, base } = await serve());
});

after(() => server.close());

/** A state beyond the critical angle: glass to air at 53°, as `--state` reads it. */
const BEYOND_CRITICAL = '{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}';

/** The θi and θt the diagram's banner gives (`θi = 40°   θt = 25.4°`). */
function angles(words) {
  const read = (name) => {
    const found = words.match(new RegExp(`${name} = (-?[0-9.]+)°`));
    return found ? Number(found[1]) : null;
  };
  return { i: read('θi'), t: read('θt') };
}

test('the page loads with no console error and draws the diagram', async () => {
  await inBrowser(async (page) => {
    await open(page, base);
    const picture = await pixels(page);
    assert.ok(colours(picture) > 40, `only ${colours(picture)} colours: a blank canvas`);
    assert.ok(placesOf(picture, W_COLOUR).length > 200, 'W is drawn');
    const words = await said(page);
    assert.match(words, /Section 2/, words);
    assert.deepEqual(angles(words), { i: 40, t: 25.4 }, words);
    assert.equal(await page.title(), 'Refraction explorer');
  });
});

test('a #state= link opens that state: beyond the critical angle, total internal reflection', async () => {
  await inBrowser(async (page) => {
    await open(page, `${base}#state=${encodeURIComponent(BEYOND_CRITICAL)}`);
    assert.match(await said(page), /TOTAL INTERNAL REFLECTION/);
    // The plain JSON, as the address bar shows it once typed, opens too.
    await open(page, `${base}index.html#state=${BEYOND_CRITICAL}`);
    assert.match(await said(page), /TOTAL INTERNAL REFLECTION/);
  });
});

test('#lesson=snell&step=2 opens the deck at its second step', async () => {
  await inBrowser(async (page) => {
    await open(page, `${base}#lesson=snell&step=2`);
    const title = await page.title();
    assert.match(title, /· 2 \/ [0-9]+$/, title);
    // R reveals the step's answer (the canvas has the keyboard).
    const reveal = async () => {
      await page.focus('#explorer');
      await page.keyboard.press('r');
      await frames(page, 3);
      return said(page);
    };
    const second = await reveal();
    assert.match(second, /θt = /, second);
    // A new link in the same page (only the fragment changes: no reload) opens too.
    await page.evaluate(() => { location.hash = '#lesson=snell&step=1'; });
    await page.waitForFunction(() => /· 1 \/ [0-9]+$/.test(document.title));
    await frames(page, 3);
    const first = await reveal();
    assert.match(first, /θt = /, first);
    assert.notEqual(first, second, 'step 1 shows another case than step 2');
  });
});

test('dragging W\'s handle turns W and changes T', async () => {
  await inBrowser(async (page) => {
    await open(page, base);
    const before = angles(await said(page));
    const handle = await wHandle(page);
    // Away from the normal (W points along the ray, down and to the right): towards
    // grazing incidence.
    await drag(page, handle, 90, -40);
    const after = angles(await said(page));
    assert.ok(after.i !== null && after.t !== null, 'still refracted');
    assert.ok(after.i > before.i + 5, `θi ${before.i}° → ${after.i}°`);
    assert.ok(after.t > before.t + 2, `θt ${before.t}° → ${after.t}°`);
    // Snell's law holds for what is shown: 1·sin θi = 1.5·sin θt.
    const sin = (d) => Math.sin((d * Math.PI) / 180);
    assert.ok(Math.abs(sin(after.i) - 1.5 * sin(after.t)) < 0.01, JSON.stringify(after));
  });
});

test('the single file works from file://, links included', async () => {
  await inBrowser(async (page) => {
    const file = pathToFileURL(path.join(WEB, 'refraction-explorer.html')).href;
    await open(page, file);
    const picture = await pixels(page);
    assert.ok(colours(picture) > 40, 'drawn');
    assert.ok(placesOf(picture, W_COLOUR).length > 200, 'W is drawn');
    await page.goto(`${file}#state=${encodeURIComponent(BEYOND_CRITICAL)}`);
    await page.reload();
    await ready(page);
    assert.match(await said(page), /TOTAL INTERNAL REFLECTION/);
  });
});

test('a malformed, cut-short or newer link says why and leaves the default', async () => {
  await inBrowser(async (page) => {
    const encoded = encodeURIComponent(BEYOND_CRITICAL);
    const cases = [
      [`#state=${encoded.slice(0, 30)}`, /cut short/],
      ['#state=%7Bnot%20json%7D', /damaged/],
      ['#lesson=snell&step=99', /has [0-9]+ steps, not 99/],
      ['#lesson=nonesuch', /no built-in lesson called nonesuch/],
      ['#lesson=snell&v=2', /newer version/],
    ];
    for (const [fragment, why] of cases) {
      await open(page, `${base}${fragment}`);
      await page.reload();
      await ready(page);
      const words = await status(page);
      assert.match(words, /This link could not be opened/, `${fragment}: ${words}`);
      assert.match(words, why, `${fragment}: ${words}`);
      assert.doesNotMatch(await said(page), /TOTAL INTERNAL REFLECTION/, fragment);
      const picture = await pixels(page);
      assert.ok(colours(picture) > 40, `${fragment}: a blank page`);
    }
  });
});

test('a first visit speaks the browser\'s language', async () => {
  await inBrowser(async (page) => {
    await open(page, base);
    const words = await said(page);
    assert.match(words, /^Abschnitt 2: W ist die Ausbreitungsrichtung/, words);
    assert.match(words, /θt = 25,4°/, 'German writes a decimal comma');
  }, 'de-DE');
});

test('the last state is kept in the browser\'s storage', async () => {
  await inBrowser(async (page) => {
    await open(page, base);
    await drag(page, await wHandle(page), 90, -40);
    const dragged = await said(page);
    // The window writes its storage every 5 s.
    await page.waitForTimeout(6000);
    await page.reload();
    await ready(page);
    assert.equal(await said(page), dragged);
  });
});
