// The web build as a screen reader and a keyboard reach it, in headless Chromium at 1280×720
// with its accessibility tree on (--force-renderer-accessibility): what the tree holds (CDP's
// Accessibility.getFullAXTree), where Tab goes and what the arrow keys do, what the live region
// says, and what axe-core finds against WCAG 2.1 A and AA. Run after `cargo xtask web`.

import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { after, before, test } from 'node:test';

import { frames, inBrowser, open, serve } from './browser.mjs';

const axeSource = createRequire(import.meta.url)('axe-core').source;

let server;
let base;

before(async () => {
  ({ server, base } = await serve());
});

after(() => server.close());

/** Runs `check` on a new page of a browser with its accessibility tree on, speaking `locale`. */
function withTree(check, locale = 'en-US') {
  return inBrowser(check, locale, ['--force-renderer-accessibility']);
}

/** The nodes a screen reader gets: { role, name, value, description } of each one not ignored. */
async function tree(page, context) {
  const cdp = await context.newCDPSession(page);
  const { nodes } = await cdp.send('Accessibility.getFullAXTree');
  await cdp.detach();
  const property = (node, name) => node.properties?.find((p) => p.name === name)?.value?.value;
  return nodes
    .filter((node) => !node.ignored)
    .map((node) => ({
      role: node.role?.value ?? '',
      name: node.name?.value ?? '',
      value: String(node.value?.value ?? ''),
      description: node.description?.value ?? '',
      valuetext: property(node, 'valuetext') ?? '',
    }));
}

/** The node of `role` named `name`, or a failure listing what the tree holds. */
function named(nodes, role, name) {
  const found = nodes.find((n) => n.role === role && n.name === name);
  const listed = nodes.map((n) => `${n.role} "${n.name}" ${n.value}`).join('\n');
  assert.ok(found, `no ${role} named "${name}" in:\n${listed}`);
  return found;
}

/** Every word the tree gives a screen reader: names, values and descriptions. */
function reachable(nodes) {
  return nodes.map((n) => [n.name, n.value, n.valuetext, n.description].join(' ')).join('\n');
}

/** What the page's polite live region says now. */
async function liveRegion(page) {
  return page.evaluate(() => {
    const region = document.querySelector('[aria-live="polite"]');
    return region ? region.textContent : '';
  });
}

/** The id of the element that has the keyboard. */
async function focused(page) {
  return page.evaluate(() => document.activeElement?.id ?? '');
}

/** Presses `key` and lets the window take it. */
async function press(page, key) {
  await page.keyboard.press(key);
  await frames(page, 4);
}

/** Waits until the live region says something matching `pattern`; resolves to what it says. */
async function heard(page, pattern) {
  await page.waitForFunction(
    (source) => new RegExp(source).test(document.querySelector('[aria-live="polite"]')?.textContent ?? ''),
    pattern.source,
    { timeout: 10_000 },
  );
  return liveRegion(page);
}

/** A state from glass into air at 41°, just short of the critical angle (41.8°). */
const SHORT_OF_CRITICAL = '{"w":[0.656059,-0.75471,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}';

/** A state beyond the critical angle: glass to air at 53°. */
const BEYOND_CRITICAL = '{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}';

test('the tree holds a control for θi and one for each index, each with its value', async () => {
  await withTree(async (page, context) => {
    await open(page, base);
    assert.equal(await page.getAttribute('html', 'lang'), 'en');
    const nodes = await tree(page, context);
    // Each control: its number, and its value in words with the unit (its value text, which
    // Chromium gives as the number for a native input, and its description).
    const said = (node) => `${node.value} · ${node.valuetext} · ${node.description}`;
    const incidence = named(nodes, 'slider', 'Angle of incidence θi (W)');
    assert.equal(said(incidence), '40 · 40 · 40°');
    const normal = named(nodes, 'slider', 'Direction of the normal N');
    assert.equal(said(normal), '0 · 0 · straight up');
    const indexI = named(nodes, 'spinbutton', 'Index μi of the ray\'s medium');
    assert.match(said(indexI), /^1\.000293[0-9]* · 1\.000293 · 1\.000293 \(air\)$/);
    const indexT = named(nodes, 'spinbutton', 'Index μt of the medium entered');
    assert.match(said(indexT), /^1\.5 · 1\.50* · 1\.5 \(glass\)$/);
    // The picture is described in words, the hidden text field named.
    const words = reachable(nodes);
    assert.match(words, /T bends toward the normal, 25\.4° from it/);
    assert.ok(!nodes.some((n) => n.role === 'textbox' && n.name === ''), 'no unnamed text field');
  });
});

test('beyond the critical angle the words a screen reader reaches say total internal reflection', async () => {
  await withTree(async (page, context) => {
    await open(page, `${base}#state=${encodeURIComponent(BEYOND_CRITICAL)}`);
    const words = reachable(await tree(page, context));
    assert.match(words, /total internal reflection/i);
    assert.match(words, /critical angle θc = 41\.8°/);
  });
});

test('Tab reaches the angle control, and the arrow keys change it and what is said', async () => {
  await withTree(async (page) => {
    await open(page, base);
    let presses = 0;
    while ((await focused(page)) !== 'control-incidence') {
      presses += 1;
      assert.ok(presses <= 60, 'Tab never left the canvas for the angle control');
      await press(page, 'Tab');
    }
    // The bar shows once a control in it has the keyboard, with a focus ring.
    const bar = await page.locator('#explorer-controls').boundingBox();
    assert.ok(bar.height >= 44 && bar.width > 600, JSON.stringify(bar));
    const ring = await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle);
    assert.equal(ring, 'solid');
    await press(page, 'ArrowRight');
    assert.equal(await page.inputValue('#control-incidence'), '41');
    assert.equal(await page.getAttribute('#control-incidence', 'aria-valuetext'), '41°');
    assert.equal(
      await heard(page, /θi 40° → 41°/),
      'θi 40° → 41°: T at 25.9° from the normal.',
    );
    await page.waitForFunction(() => /θi = 41° from the normal/.test(document.getElementById('diagram-words').textContent));
    // No trap: Shift+Tab goes back through the page's controls and into the canvas; with no
    // widget of the window selected, Shift+Tab on the canvas comes back out.
    await press(page, 'Tab');
    assert.equal(await focused(page), 'control-normal');
    for (let i = 0; i < 3; i++) await press(page, 'Tab');
    assert.equal(await focused(page), 'explorer', 'the canvas after the controls');
    await press(page, 'Shift+Tab');
    assert.equal(await focused(page), 'control-index-t', 'Shift+Tab leaves the canvas');
  });
});

test('total internal reflection is said once when it begins and once when it ends', async () => {
  await withTree(async (page) => {
    await open(page, `${base}#state=${encodeURIComponent(SHORT_OF_CRITICAL)}`);
    await page.focus('#control-incidence');
    await frames(page, 3);
    await press(page, 'ArrowRight');
    assert.equal(
      await heard(page, /θi 41° → 42°/),
      'θi 41° → 42°: now past the critical angle 41.8°; all light is reflected.',
    );
    await press(page, 'ArrowRight');
    assert.equal(await heard(page, /θi 42° → 43°/), 'θi 42° → 43°.', 'not said again');
    await press(page, 'ArrowLeft');
    await heard(page, /θi 43° → 42°\.$/);
    await press(page, 'ArrowLeft');
    assert.match(
      await heard(page, /θi 42° → 41°/),
      /^θi 42° → 41°: now short of the critical angle 41\.8°; T leaves at 7[0-9.]+° from the normal\.$/,
    );
  });
});

test('an index typed in the page\'s control changes the diagram, and the diagram the control', async () => {
  await withTree(async (page) => {
    await open(page, base);
    await page.fill('#control-index-t', '1.333');
    await page.press('#control-index-t', 'Enter');
    await frames(page, 4);
    await page.waitForFunction(() => /water \(μt = 1\.333\)/.test(document.getElementById('diagram-words').textContent));
    await page.focus('#control-normal');
    await press(page, 'ArrowRight');
    assert.equal(await page.getAttribute('#control-normal', 'aria-valuetext'), '1° right of straight up');
  });
});

test('a deck\'s step is titled, its question said and its hidden answer not, until revealed', async () => {
  await withTree(async (page, context) => {
    await open(page, `${base}#lesson=snell&step=2`);
    const title = await page.title();
    assert.match(title, /Straight down the normal · 2 \/ 5$/, title);
    const nodes = await tree(page, context);
    const words = reachable(nodes);
    assert.match(words, /Question: A ray meets the surface along the normal/);
    assert.match(words, /The answer is hidden/);
    assert.doesNotMatch(words, /does not bend/);
    // The page's own buttons step through the deck and reveal the answer.
    named(nodes, 'button', 'Previous step');
    named(nodes, 'button', 'Next step');
    await page.getByRole('button', { name: 'Reveal the answer' }).press('Enter');
    assert.match(await heard(page, /does not bend/), /^Step 2 of 5: Straight down the normal\./);
    await page.getByRole('button', { name: 'Hide the answer' }).waitFor();
    await page.getByRole('button', { name: 'Next step' }).press('Enter');
    await page.waitForFunction(() => / 3 \/ 5$/.test(document.title));
  });
});

test('the page speaks the language it shows', async () => {
  await withTree(async (page, context) => {
    await open(page, base);
    assert.equal(await page.getAttribute('html', 'lang'), 'de');
    const nodes = await tree(page, context);
    named(nodes, 'slider', 'Einfallswinkel θi (W)');
    assert.match(reachable(nodes), /T wird zum Lot hin gebrochen/);
  }, 'de-DE');
});

/** The serious and critical WCAG 2.1 A and AA violations axe-core finds on the page now. */
async function violations(page) {
  await page.addScriptTag({ content: axeSource });
  const found = await page.evaluate(async () => {
    const result = await window.axe.run(document, {
      runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] },
    });
    return result.violations.map((v) => ({
      id: v.id,
      impact: v.impact,
      nodes: v.nodes.map((n) => n.html),
    }));
  });
  return found.filter((v) => v.impact === 'serious' || v.impact === 'critical');
}

test('axe-core finds no serious or critical WCAG 2.1 A or AA violation', async () => {
  await withTree(async (page) => {
    await open(page, base);
    assert.deepEqual(await violations(page), [], 'at rest');
    await page.focus('#control-incidence');
    await frames(page, 3);
    assert.deepEqual(await violations(page), [], 'with the controls shown');
    await open(page, `${base}#lesson=total-internal-reflection&step=3`);
    assert.deepEqual(await violations(page), [], 'at a deck\'s step');
  });
});
