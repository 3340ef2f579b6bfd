// SPDX-License-Identifier: MIT
// The page in a real browser: Debian's Chromium, headless, driven by puppeteer-core. Loads the built page from a
// local server, checks that the console has no errors, presses keys through the tour (step, back, play, pause) and
// reads the page's state line (web/shell.html #state, written by the window each frame), and takes screenshots.
//   node page_test.js URL OUT_DIR
'use strict';
const puppeteer = require('puppeteer-core');
const path = require('path');

const [url, out] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { console.log((ok ? 'ok   ' : 'FAIL ') + what); if (!ok) failures.push(what); };

(async () => {
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium', headless: true, userDataDir: path.join(out, 'profile'),
    // as root, without a GPU (WebGL 2 through SwiftShader), and without calls to Google's services
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync', '--window-size=1280,800'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({width: 1280, height: 800});
    const errors = [];
    page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('pageerror', e => errors.push(e.message));
    const opened = Date.now();
    await page.goto(url);
    const state = () => page.$eval('#state', e => e.textContent);
    const waitFor = async (pattern, ms = 20000) => {
      const until = Date.now() + ms;
      for (let s = await state(); Date.now() < until; s = await state()) {
        if (pattern.test(s)) return s;
        await new Promise(r => setTimeout(r, 50));
      }
      return await state();
    };
    const first = await waitFor(/^step 0 of \d+/);
    check(/^step 0 of 64, paused/.test(first), `the tour opens at its first step: "${first}"`);
    console.log(`first frame after ${Date.now() - opened} ms`);
    await page.screenshot({path: path.join(out, 'opened.png')});

    const press = async (key, times = 1) => { for (let k = 0; k < times; ++k) await page.keyboard.press(key); };
    await page.focus('#canvas');
    await press('ArrowRight', 3);
    check(/^step 3 of 64/.test(await waitFor(/^step 3 of/)), '→ three times: step 3');
    await press('ArrowLeft');
    check(/^step 2 of 64/.test(await waitFor(/^step 2 of/)), '← once: step 2');
    await press('Space');
    check(/playing/.test(await waitFor(/playing/)), 'Space plays');
    await press('Space');
    check(/paused/.test(await waitFor(/paused/)), 'Space again pauses');
    await page.screenshot({path: path.join(out, 'stepped.png')});
    check(errors.length === 0, 'no errors in the console' + (errors.length ? ': ' + errors.join(' | ') : ''));
  } finally {
    await browser.close();
  }
  if (failures.length) { console.log(`${failures.length} failed`); process.exit(1); }
  console.log('page_test: ok');
})().catch(e => { console.error(e); process.exit(1); });
