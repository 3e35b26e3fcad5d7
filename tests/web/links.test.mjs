// Links and the browser's storage under hostile use (issue 40): what a strip echoes is
// bounded and the diagram stays shown, Esc closes the strip, and a link or a kept state that
// cannot be used says why. Run after `cargo xtask web`: `npm test` in this folder.

import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import {
  W_COLOUR, colours, inBrowser, open, pixels, placesOf, ready, serve, status,
} from './browser.mjs';

let server;
let base;

before(async () => {
  ({ server, base } = await serve());
});

after(() => server.close());

/** Opens `fragment` on a page that was showing the default (a link followed in place). */
async function follow(page, fragment) {
  await open(page, `${base}${fragment}`);
  await page.reload();
  await ready(page);
}

/** W's pixels on the page: the diagram is shown when there are many. */
async function wShown(page) {
  return placesOf(await pixels(page), W_COLOUR).length;
}

test('a link with a 20,000-character lesson name says so in one short strip, the diagram shown, and Esc closes it', async () => {
  await inBrowser(async (page) => {
    const name = 'x'.repeat(20_000);
    await follow(page, `#lesson=${name}`);
    const words = await status(page);
    assert.match(words, /no built-in lesson called x+… \(\+19940\)/, words.slice(0, 200));
    assert.ok(words.length < 400, `the strip echoes ${words.length} characters`);
    assert.ok(await wShown(page) > 200, 'W is drawn: the diagram is shown');
    const withStrip = await pixels(page);
    assert.ok(colours(withStrip) > 40, 'a page, not a wall of text');
    await page.mouse.click(640, 400);
    await page.keyboard.press('Escape');
    await page.waitForFunction(() => document.getElementById('status').textContent === '');
    assert.ok(await wShown(page) > 200, 'the diagram after the strip closed');
  });
});

test('a state given twice, an unknown field, a nameless part or a megabyte name each say why', async () => {
  await inBrowser(async (page) => {
    const state = encodeURIComponent('{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}');
    const zoomed = encodeURIComponent('{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1,"zoom":2}');
    const cases = [
      [`#state=${state}&state=${state}`, /the link gives state twice/],
      [`#state=${zoomed}`, /newer version of the explorer \(zoom\)/],
      ['#===', /a part of the link has no name/],
      [`#lesson=snell&${'q'.repeat(1_900_000)}=1`, /newer version of the explorer \(q+… \(\+1899940\)\)/],
    ];
    for (const [fragment, why] of cases) {
      await follow(page, fragment);
      const words = await status(page);
      assert.match(words, /This link could not be opened/, `${fragment.slice(0, 80)}: ${words}`);
      assert.match(words, why, `${fragment.slice(0, 80)}: ${words}`);
      assert.ok(words.length < 400, `${words.length} characters`);
      assert.ok(await wShown(page) > 200, `${fragment.slice(0, 80)}: the diagram is shown`);
    }
  });
});

test('a kept state that cannot be read, or a kept address that cannot start a link, is said', async () => {
  await inBrowser(async (page) => {
    // What a damaged storage holds, written before the explorer's first run reads it.
    await page.addInitScript(() => {
      if (!sessionStorage.getItem('damaged')) {
        sessionStorage.setItem('damaged', '1');
        localStorage.setItem('explorer_state', '{"w":[0.6,-0.8');
        localStorage.setItem('explorer_web_base', 'javascript:alert(1)');
      }
    });
    await open(page, base);
    const words = await status(page);
    assert.match(words, /The state kept from last time could not be read/, words);
    assert.match(words, /The web address kept from last time is not used: it starts with “javascript”/, words);
    assert.ok(await wShown(page) > 200, 'the default state is shown');
  });
});
