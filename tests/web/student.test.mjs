// The student's view in a real browser (issue 41): what a QR code or a link opens on a phone,
// driven with one finger and two through the Chrome DevTools Protocol's touch events
// (Input.dispatchTouchEvent), at a phone's size upright (390 × 844 CSS px) and sideways
// (844 × 390), and on an upright tablet (820 × 1180). Run after `cargo xtask web`:
// `npm test` in this folder.

import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';

import {
  W_COLOUR, close, frames, launch, newPage, open, pixels, placesOf, said, serve, wHandle,
} from './browser.mjs';

let server;
let base;

before(async () => {
  ({ server, base } = await serve());
});

after(() => server.close());

const PHONE = { width: 390, height: 844 };
const PHONE_SIDEWAYS = { width: 844, height: 390 };
const TABLET = { width: 820, height: 1180 };

/** The surface line's colour: the diagram's ink (refraction_diagram::palette::INK, #202020). */
const INK = [0x20, 0x20, 0x20];

/** Runs `check` on a new page of a touch-screen browser of `size` with a fresh profile. */
async function onTouchScreen(size, check) {
  const context = await launch(size, 'en-US', { hasTouch: true, isMobile: true });
  try {
    const page = await newPage(context);
    await check(page, await context.newCDPSession(page));
    assert.deepEqual(page.errors, [], 'no console error');
  } finally {
    await close(context);
  }
}

/**
 * One finger (or two: `paths` holds each finger's path) pressed, moved in `steps` steps with a
 * frame after each, and lifted, as a touch screen sends it.
 */
async function touch(page, cdp, paths, steps = 12) {
  const at = (i) => paths.map(([from, to], id) => ({
    x: from.x + ((to.x - from.x) * i) / steps,
    y: from.y + ((to.y - from.y) * i) / steps,
    id,
  }));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  await frames(page, 2);
  for (let i = 1; i <= steps; i++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(i) });
    await frames(page, 1);
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await frames(page, 3);
}

/**
 * The row with the most of the diagram's ink in the picture: the surface line, drawn across
 * the diagram's width (N and W cross it), its y and how many pixels it has.
 */
function surfaceLine(picture) {
  const { width, height, data } = picture;
  let best = { y: -1, length: 0 };
  for (let y = 0; y < height; y++) {
    let count = 0;
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      if (INK.every((c, k) => Math.abs(data[i + k] - c) <= 24)) count += 1;
    }
    if (count > best.length) best = { y, length: count };
  }
  return best;
}

/** Which view the page shows, as the page says on its canvas (`student` or `teacher`). */
async function view(page) {
  return page.getAttribute('#explorer', 'data-view');
}

/** The angle of incidence the diagram's banner says (after the reveal), in degrees. */
async function incidence(page) {
  const found = (await said(page)).match(/θi = (-?[0-9.]+)°/);
  return found ? Number(found[1]) : null;
}

/** Reveals the step's answer with the deck's key, so that the banner gives the angles. */
async function reveal(page) {
  await page.focus('#explorer');
  await page.keyboard.press('r');
  await frames(page, 3);
}

test('a phone opens #lesson=snell&step=2 in the student view: the diagram across, W drawn, no notes', async () => {
  await onTouchScreen(PHONE, async (page) => {
    await open(page, `${base}#lesson=snell&step=2`);
    assert.equal(await view(page), 'student');
    const picture = await pixels(page);
    const surface = surfaceLine(picture);
    assert.ok(
      surface.length >= 0.8 * PHONE.width,
      `the diagram is ${surface.length} of ${PHONE.width} px wide`,
    );
    // At normal incidence W lies along N, under it: its handle's ring shows.
    assert.ok(placesOf(picture, W_COLOUR).length > 40, 'W is drawn');
    // The notes' key does nothing here: the teacher's notes never show on a student's page.
    await page.focus('#explorer');
    await page.keyboard.press('n');
    await frames(page, 3);
    assert.deepEqual(await pixels(page), picture, 'nothing opened');
    assert.equal(await view(page), 'student');
  });
});

test('one finger on W\'s handle turns W on a phone', async () => {
  await onTouchScreen(PHONE, async (page, cdp) => {
    await open(page, `${base}#lesson=snell&step=1`);
    const handle = await wHandle(page);
    const before = await pixels(page);
    // Toward grazing incidence: W's tip (the handle, at its tail while the answer is hidden)
    // moves out and down.
    await touch(page, cdp, [[handle, { x: handle.x - 80, y: handle.y + 60 }]]);
    assert.notDeepEqual(await pixels(page), before, 'the diagram changed');
    await reveal(page);
    const turned = await incidence(page);
    assert.ok(turned !== null && turned > 45, `θi 40° → ${turned}°`);
  });
});

test('one finger pans the diagram where nothing is grabbed, and two fingers zoom it', async () => {
  await onTouchScreen(PHONE, async (page, cdp) => {
    await open(page, `${base}#lesson=snell&step=1`);
    const start = surfaceLine(await pixels(page));
    // Below the surface, in the empty second medium (the answer is hidden there).
    const from = { x: PHONE.width / 2 + 60, y: start.y + 60 };
    await touch(page, cdp, [[from, { x: from.x, y: from.y + 80 }]]);
    const panned = surfaceLine(await pixels(page));
    assert.ok(Math.abs(panned.y - start.y - 80) <= 6, `the surface moved from y ${start.y} to ${panned.y}`);
    const wBefore = placesOf(await pixels(page), W_COLOUR).length;
    // Two fingers apart, about the point where the ray meets the surface.
    const middle = { x: PHONE.width / 2, y: panned.y + 20 };
    await touch(page, cdp, [
      [{ x: middle.x - 40, y: middle.y }, { x: middle.x - 70, y: middle.y }],
      [{ x: middle.x + 40, y: middle.y }, { x: middle.x + 70, y: middle.y }],
    ]);
    const wAfter = placesOf(await pixels(page), W_COLOUR).length;
    assert.ok(wAfter > wBefore * 1.3, `W's pixels ${wBefore} → ${wAfter}: zoomed in`);
  });
});

test('a phone held sideways and an upright tablet get the student view too', async () => {
  for (const [size, share] of [[PHONE_SIDEWAYS, 0.6], [TABLET, 0.95]]) {
    await onTouchScreen(size, async (page) => {
      await open(page, `${base}#lesson=total-internal-reflection&step=3`);
      assert.equal(await view(page), 'student', JSON.stringify(size));
      const surface = surfaceLine(await pixels(page));
      assert.ok(surface.length >= share * size.width, `${JSON.stringify(size)}: ${surface.length} px`);
    });
  }
});

test('on a desk\'s screen the teacher\'s view stays, and a finger scrolls its panels', async () => {
  await onTouchScreen({ width: 1280, height: 720 }, async (page, cdp) => {
    await open(page, `${base}#lesson=snell&step=1`);
    assert.equal(await view(page), 'teacher');
    // The controls panel (left) is taller than the window: a finger's drag up scrolls it.
    const panel = { x: 150, y: 600 };
    const clip = { x: 0, y: 100, width: 290, height: 600 };
    const before = await page.screenshot({ clip });
    await touch(page, cdp, [[panel, { x: panel.x, y: panel.y - 300 }]]);
    const after = await page.screenshot({ clip });
    assert.notDeepEqual(after, before, 'the panel scrolled');
  });
});
