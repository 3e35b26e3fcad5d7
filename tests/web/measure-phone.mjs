// How fast the student's view is on a phone-class processor, measured (not a test: figures for
// docs/web.md). Run after `cargo xtask web`: `node measure-phone.mjs` in this folder. Chromium
// at a phone's size (390 × 844 CSS px, touch) with its processor slowed four times (the Chrome
// DevTools Protocol's Emulation.setCPUThrottlingRate, the usual stand-in for a mid-range
// phone); for each of five runs in a fresh profile:
// - the time from navigation to the first drawn frame of `#lesson=snell&step=1`;
// - the window's own time for each frame while one finger drags W's handle (eframe's frame
//   time: the UI pass, its tessellation and the WebGL calls), median and 95th percentile, and
//   all of the page's main thread per touch move (Chromium's TaskDuration, software WebGL
//   included: the machine has no GPU).
// Prints one JSON object with the medians over the runs.

import {
  close, firstFrameAt, frames, launch, mainThreadMs, newPage, recordFrameTimes, serve, wHandle,
} from './browser.mjs';

const RUNS = 5;
const MOVES = 60;
const THROTTLING = 4;
const PHONE = { width: 390, height: 844 };

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

function percentile95(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.floor(sorted.length * 0.95))];
}

/** One run: the first frame's time and a finger's drag of W, in ms. */
async function run(url) {
  const context = await launch(PHONE, 'en-US', { hasTouch: true, isMobile: true });
  const page = await newPage(context);
  const cdp = await context.newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: THROTTLING });
  const first = await firstFrameAt(page, url);
  await frames(page, 5);
  const handle = await wHandle(page);
  await cdp.send('Performance.enable');
  const busy = () => mainThreadMs(cdp);
  const point = (i) => {
    const angle = (i / MOVES) * Math.PI;
    return { x: handle.x - 70 * Math.sin(angle), y: handle.y + 40 * Math.sin(angle / 2), id: 0 };
  };
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [point(0)] });
  await frames(page, 2);
  await recordFrameTimes(page);
  const start = await busy();
  for (let i = 1; i <= MOVES; i++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [point(i)] });
    await frames(page, 1);
  }
  const spent = (await busy()) - start;
  const times = await page.evaluate(() => window.frameTimes);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  if (page.errors.length) throw new Error(page.errors.join('\n'));
  await close(context);
  return { first, frame: median(times), frame95: percentile95(times), frames: times.length, page: spent / MOVES };
}

const { server, base } = await serve();
const runs = [];
for (let i = 0; i < RUNS; i++) runs.push(await run(`${base}#lesson=snell&step=1`));
server.close();
const round = (x) => Math.round(x * 10) / 10;
console.log(JSON.stringify({
  cpu_throttling: THROTTLING,
  first_frame_ms_median: round(median(runs.map((r) => r.first))),
  drag_frame_ms_median: round(median(runs.map((r) => r.frame))),
  drag_frame_ms_p95_median: round(median(runs.map((r) => r.frame95))),
  page_ms_per_touch_move_median: round(median(runs.map((r) => r.page))),
  runs: runs.map((r) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, round(v)]))),
}, null, 2));
