// SPDX-License-Identifier: MIT
// A benchmark, not a test: how long the page's frames take, lesson by lesson, in Debian's headless Chromium (WebGL 2
// through SwiftShader, a software renderer: a GPU is faster). Each lesson is opened from its link at 1280×800 and
// played (Space) for a few seconds; the page's own frame log (web/platform_web.cpp: the work of each drawn frame,
// not the display's pacing) gives the median and the 90th percentile. Prints a table; asserts nothing.
//   node frame_times.js URL LESSONS_DIR [SECONDS]
'use strict';
const puppeteer = require('puppeteer-core');
const fs = require('fs');

const [url, lessons, seconds = '3'] = process.argv.slice(2);
const sleep = ms => new Promise(r => setTimeout(r, ms));
const quantile = (sorted, q) => sorted.length ? sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))] : NaN;

(async () => {
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync', '--window-size=1280,800'],
  });
  const names = fs.readdirSync(lessons).filter(f => /^\d\d_.*\.toml$/.test(f)).map(f => f.replace(/\.toml$/, '')).sort();
  const medians = [];
  console.log('lesson                           frames  median ms  p90 ms  first frame ms');
  try {
    for (const name of names) {
      const page = await browser.newPage();
      await page.setViewport({width: 1280, height: 800});
      const opened = Date.now();
      await page.goto(`${url}#lesson=${name}`);
      await page.waitForFunction(() => /^step \d+ of/.test(document.getElementById('state').textContent), {timeout: 30000});
      const first = Date.now() - opened;
      await page.focus('#canvas');
      await page.evaluate(() => { Module.frame_log.length = 0; });
      await page.keyboard.press('Space');
      await sleep(1000 * Number(seconds));
      const log = (await page.evaluate(() => Module.frame_log.slice())).sort((a, b) => a - b);
      const median = quantile(log, 0.5);
      medians.push(median);
      console.log(`${name.padEnd(32)} ${String(log.length).padStart(6)} ${median.toFixed(2).padStart(10)} ${quantile(log, 0.9).toFixed(2).padStart(7)} ${String(first).padStart(15)}`);
      await page.close();
    }
  } finally {
    await browser.close();
  }
  const sorted = medians.slice().sort((a, b) => a - b);
  console.log(`${names.length} lessons: the median of their medians ${quantile(sorted, 0.5).toFixed(2)} ms, the largest ${sorted[sorted.length - 1].toFixed(2)} ms`);
})().catch(e => { console.error(e); process.exit(1); });
