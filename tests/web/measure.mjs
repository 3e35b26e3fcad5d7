// How small and fast the web build is, measured (not a test: figures for docs/web.md).
// Run after `cargo xtask web`: `node measure.mjs` in this folder. Prints one JSON object:
// - the module's size, raw and gzipped (level 9), and the single file's size;
// - the time from the page's load (navigation start) to its first drawn frame in headless
//   Chromium, over the folder's page served on 127.0.0.1 and the single file from file://;
// - the CPU time of a frame while W is dragged, as the window measures it (eframe's frame
//   time, read from the browser's performance entries), and all of the page's main thread per
//   pointer move (TaskDuration), software WebGL included.

import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { pathToFileURL } from 'node:url';

import {
  WEB, close, firstFrameAt, frames, launch, mainThreadMs, newPage, recordFrameTimes, serve, wHandle,
} from './browser.mjs';

const RUNS = 5;
const DRAG_FRAMES = 60;

/** The median of `values`. */
function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

/**
 * Milliseconds from navigation start to the first frame drawn: the first animation frame
 * after the explorer named its canvas (which it does at the end of its first frame).
 */
async function firstFrame(context, url) {
  const page = await newPage(context);
  const ms = await firstFrameAt(page, url);
  if (page.errors.length) throw new Error(page.errors.join('\n'));
  await page.close();
  return ms;
}

/**
 * What a frame costs while W is dragged across the diagram, in ms: `frame`, the median of the
 * window's own measure of its frames (eframe's: the UI pass, tessellation and the WebGL calls
 * that paint it), `frames` how many it drew; `page`, all the main thread's busy time per
 * pointer move (Chromium's TaskDuration), which here includes drawing WebGL in software
 * (SwiftShader: the machine has no GPU).
 */
async function dragFrame(context, url) {
  const page = await newPage(context);
  await page.goto(url);
  await page.waitForFunction(() => document.getElementById('explorer').getAttribute('aria-label'));
  await frames(page, 5);
  const handle = await wHandle(page);
  const cdp = await context.newCDPSession(page);
  await cdp.send('Performance.enable');
  const busy = () => mainThreadMs(cdp);
  await page.mouse.move(handle.x, handle.y);
  await page.mouse.down();
  await frames(page, 2);
  await recordFrameTimes(page);
  const start = await busy();
  for (let i = 1; i <= DRAG_FRAMES; i++) {
    const angle = (i / DRAG_FRAMES) * Math.PI;
    await page.mouse.move(handle.x + 60 * Math.sin(angle), handle.y - 30 * Math.sin(angle / 2));
    await frames(page, 1);
  }
  const spent = (await busy()) - start;
  const measured = await page.evaluate(() => window.frameTimes);
  await page.mouse.up();
  await page.close();
  return { frame: median(measured), frames: measured.length, page: spent / DRAG_FRAMES };
}

const wasm = fs.readFileSync(path.join(WEB, 'refraction_web_bg.wasm'));
const single = fs.statSync(path.join(WEB, 'refraction-explorer.html')).size;
const { server, base } = await serve();
const file = pathToFileURL(path.join(WEB, 'refraction-explorer.html')).href;
const served = [];
const fromFile = [];
const drags = [];
for (let run = 0; run < RUNS; run++) {
  // A fresh profile each time: nothing cached, nothing saved.
  const context = await launch();
  served.push(await firstFrame(context, base));
  fromFile.push(await firstFrame(context, file));
  drags.push(await dragFrame(context, base));
  await close(context);
}
server.close();
const round = (x) => Math.round(x * 10) / 10;
console.log(JSON.stringify({
  wasm_bytes: wasm.length,
  wasm_gzip_bytes: zlib.gzipSync(wasm, { level: 9 }).length,
  single_file_bytes: single,
  first_frame_ms: { served_median: round(median(served)), file_median: round(median(fromFile)), served, file: fromFile },
  drag_frame_cpu_ms: {
    frame_median: round(median(drags.map((d) => d.frame))),
    page_with_software_webgl_median: round(median(drags.map((d) => d.page))),
    runs: drags.map((d) => ({ frame: round(d.frame), frames: d.frames, page: round(d.page) })),
  },
  runs: RUNS,
}, null, 2));
