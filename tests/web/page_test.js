// SPDX-License-Identifier: MIT
// The page in a real browser: Debian's Chromium, headless, driven by puppeteer-core. Loads the built page from a
// local server and, on each page, checks that the console has no errors:
//   - the tour: it opens at step 0; → ← step; Space plays and pauses (read from the page's state line, #state);
//   - the same keys on lesson 01 in the page and in the desktop build (offscreen): the same state line and the same
//     hash of the events played; then N (the next lesson), X (practice) and an answer;
//   - a link (#lesson=05_bsp_traversal&step=12) opens that lesson at that step, and the address follows the player;
//   - files of one's own: O's file picker and a drop on the window open a lesson with its scene; E offers the export
//     as downloads;
//   - the settings persist: the language chosen with L is the language after the page is opened again;
//   - #projector: larger type.
// It takes screenshots of each (OUT_DIR/*.png) to look at.
//   node page_test.js URL OUT_DIR DESKTOP_HSRVIZ LESSONS_DIR
'use strict';
const puppeteer = require('puppeteer-core');
const {execFileSync} = require('child_process');
const fs = require('fs');
const path = require('path');

const [url, out, desktop, lessons] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { console.log((ok ? 'ok   ' : 'FAIL ') + what); if (!ok) failures.push(what); };
const sleep = ms => new Promise(r => setTimeout(r, ms));
// the page's key names and the desktop's --keys names
const keys = {Right: 'ArrowRight', Left: 'ArrowLeft', Space: 'Space', End: 'End', Home: 'Home', L: 'KeyL', O: 'KeyO', E: 'KeyE',
              N: 'KeyN', X: 'KeyX',
              1: 'Digit1', 2: 'Digit2', 3: 'Digit3', 4: 'Digit4', PageDown: 'PageDown'};

// A page opened at URL#hash, with helpers: its state line, a query to the window, keys, and the console's errors.
async function open(browser, hash, name) {
  const page = await browser.newPage();
  await page.setViewport({width: 1280, height: 800});
  const errors = [];
  page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', e => errors.push(e.message));
  const opened = Date.now();
  await page.goto(url + (hash || ''));
  const p = {
    page, errors, name,
    state: () => page.$eval('#state', e => e.textContent),
    ask: question => page.evaluate(q => Module.ccall('hsr_query', 'string', ['string'], [q]), question),
    async waitFor(pattern, ms = 20000) {
      const until = Date.now() + ms;
      for (let s = await p.state(); Date.now() < until; s = await p.state()) {
        if (pattern.test(s)) return s;
        await sleep(50);
      }
      return await p.state();
    },
    async press(...names) {  // one key per animation frame or two, as a person's would arrive
      for (const n of names) {
        await page.keyboard.press(keys[n] || n);
        await page.evaluate(() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r))));
      }
    },
    async shot(file) { await page.screenshot({path: path.join(out, file)}); },
    async close() {
      check(errors.length === 0, `${name}: no errors in the console` + (errors.length ? ': ' + errors.join(' | ') : ''));
      await page.close();
    },
  };
  const first = await p.waitFor(/^step \d+ of \d+/);
  p.first = first;
  p.first_ms = Date.now() - opened;
  await page.focus('#canvas');
  return p;
}

// The desktop build after the same keys: its "at …" and "score …" lines, and its played trace
function desktop_run(lesson, key_names) {
  const config = path.join(out, 'desktop-window.toml');
  fs.rmSync(config, {force: true});
  const text = execFileSync(desktop, [path.join(lessons, lesson + '.toml'), '--screenshot', path.join(out, 'desktop.png'),
                                      '--size', '1280x800', '--frames', '3', '--keys', key_names.join(',')],
                            {env: {...process.env, SDL_VIDEODRIVER: 'offscreen', HSRVIZ_CONFIG: config}, encoding: 'utf8'});
  const at = /^hsrviz: at (.*)$/m.exec(text), score = /^hsrviz: score (\d+) of (\d+) answered/m.exec(text);
  const trace = /^hsrviz: played trace ([0-9a-f]{16} \d+)$/m.exec(text);
  return {state: at && at[1] + (score ? `, score ${score[1]} of ${score[2]}` : ''), trace: trace && trace[1]};
}

(async () => {
  fs.rmSync(path.join(out, 'profile'), {recursive: true, force: true});  // a browser that has never seen the page
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium', headless: true, userDataDir: path.join(out, 'profile'),
    // as root, without a GPU (WebGL 2 through SwiftShader), and without calls to Google's services
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync', '--window-size=1280,800'],
  });
  try {
    // 1. the tour: step, back, play, pause
    let p = await open(browser, '', 'the tour');
    check(/^step 0 of 64, paused/.test(p.first), `the tour opens at its first step: "${p.first}"`);
    console.log(`first frame after ${p.first_ms} ms`);
    await p.shot('opened.png');
    await p.press('Right', 'Right', 'Right');
    check(/^step 3 of 64/.test(await p.waitFor(/^step 3 of/)), '→ three times: step 3');
    await p.press('Left');
    check(/^step 2 of 64/.test(await p.waitFor(/^step 2 of/)), '← once: step 2');
    await p.press('Space');
    check(/playing/.test(await p.waitFor(/playing/)), 'Space plays');
    await p.press('Space');
    check(/paused/.test(await p.waitFor(/paused/)), 'Space again pauses');
    await p.shot('stepped.png');
    await p.close();

    // 2. the page and the desktop after the same keys: a question held, answered wrongly, then steps on
    const script = ['Right', 'Right', 'Right', 'Right', 'Right', 'Right', 'Right', '1', 'Right', 'Right', 'End'];
    p = await open(browser, '#lesson=01_cohen_sutherland', 'lesson 01 by keys');
    await p.press(...script);
    await sleep(300);
    const page_state = await p.state(), page_trace = await p.ask('trace');
    const d = desktop_run('01_cohen_sutherland', script);
    console.log(`page:    ${page_state} | trace ${page_trace}\ndesktop: ${d.state} | trace ${d.trace}`);
    check(page_state === d.state, 'the page and the desktop stand at the same step, with the same score');
    check(page_trace === d.trace && /^[0-9a-f]{16} \d+$/.test(page_trace), 'the page and the desktop played the same events (trace hash)');
    check(/question open/.test(page_state) || /score 0 of 1/.test(page_state), `a question was asked and answered: "${page_state}"`);
    await p.shot('compared.png');
    // on through the course, and practice: N opens the next lesson; X an exercise the machine grades; a typed answer
    await p.press('N');
    check((await p.ask('lesson')).endsWith('/lessons/02_liang_barsky.toml'), `N: the next lesson (${await p.ask('lesson')})`);
    await p.press('X');
    await sleep(300);
    check(/practice/.test(await p.ask('lesson')), `X: an exercise (${await p.ask('lesson')})`);
    await p.shot('practice.png');
    await p.press('Digit0', 'Period', 'Digit5', 'Enter');  // a typed number (Liang–Barsky asks for a t)
    await sleep(300);
    check(await p.ask('practice') === 'answered 1, right 0' || await p.ask('practice') === 'answered 1, right 1',
          `0.5 Enter answers it, and the score counts it: ${await p.ask('practice')}`);
    await p.close();

    // 3. a link to a moment: the lesson and the step it names, and the address follows the player
    p = await open(browser, '#lesson=05_bsp_traversal&step=12', 'a link');
    check(/^step 12 of/.test(p.first), `#lesson=05_bsp_traversal&step=12 opens at step 12: "${p.first}"`);
    check((await p.ask('lesson')).endsWith('/lessons/05_bsp_traversal.toml'), 'and in lesson 05');
    await p.press('Right');
    await sleep(200);
    const moved = /^step (\d+) of/.exec(await p.state());
    const address = await p.page.evaluate(() => location.hash);
    check(moved && moved[1] !== '12' && address === `#lesson=05_bsp_traversal&step=${moved[1]}`, `the address follows: ${address}`);
    await p.shot('link.png');
    await p.close();

    // 4. files of one's own: O's picker, a drop, and the export as downloads
    const mine = path.join(out, 'mine');
    fs.mkdirSync(mine, {recursive: true});
    fs.copyFileSync(path.join(lessons, '..', 'assets', 'scenes', 'bsp_2d_segments.toml'), path.join(mine, 'walls.toml'));
    fs.writeFileSync(path.join(mine, 'mine.toml'), 'title = "My walls"\nalgorithm = "bsp_build"\nscene = "walls.toml"\n');
    p = await open(browser, '', 'files of my own');
    const choosing = p.page.waitForFileChooser();
    await sleep(300);  // the browser intercepts its file chooser only once it has been told to (asynchronously)
    await p.press('O');
    const chooser = await choosing;
    await chooser.accept([path.join(mine, 'walls.toml'), path.join(mine, 'mine.toml')]);
    await p.waitFor(/^step 0 of 41/, 5000);
    check(await p.ask('lesson') === '/uploads/mine.toml', `O: the lesson picked with its scene opens (${await p.ask('lesson')})`);
    check(/^step 0 of 41/.test(await p.state()), `and plays: "${await p.state()}"`);
    await p.press('Right', 'Right');
    await p.shot('picked.png');
    const downloads = path.join(out, 'downloads');
    fs.rmSync(downloads, {recursive: true, force: true});
    const cdp = await p.page.target().createCDPSession();
    await cdp.send('Browser.setDownloadBehavior', {behavior: 'allow', downloadPath: downloads});
    await p.press('E');
    const wanted = ['mine-step-2.png', 'mine.jsonl', 'mine-scene.toml'];
    for (let k = 0; k < 100 && !wanted.every(f => fs.existsSync(path.join(downloads, f))); ++k) await sleep(100);
    check(wanted.every(f => fs.existsSync(path.join(downloads, f))),
          `E: the export is downloaded (${fs.existsSync(downloads) ? fs.readdirSync(downloads).join(', ') : 'nothing'})`);
    // a drop on the window: the lesson among the files opens
    await p.page.evaluate((lesson, scene) => {
      const files = new DataTransfer();
      files.items.add(new File([scene], 'room.toml'));
      files.items.add(new File([lesson], 'dropped.toml'));
      document.getElementById('canvas').dispatchEvent(new DragEvent('drop', {dataTransfer: files, bubbles: true, cancelable: true}));
    }, fs.readFileSync(path.join(mine, 'mine.toml'), 'utf8').replace('walls.toml', 'room.toml'),
       fs.readFileSync(path.join(mine, 'walls.toml'), 'utf8'));
    for (let k = 0; k < 50 && await p.ask('lesson') !== '/uploads/dropped.toml'; ++k) await sleep(100);
    check(await p.ask('lesson') === '/uploads/dropped.toml', 'a drop: the lesson among the dropped files opens');
    await p.close();

    // 5. the settings persist in the browser: L chooses German, and the page opened again speaks it
    p = await open(browser, '', 'the language chosen');
    await p.press('L');
    check(await p.ask('language') === 'de', 'L: German');
    await sleep(1000);  // IndexedDB is written after the settings file
    await p.close();
    p = await open(browser, '', 'the page opened again');
    check(await p.ask('language') === 'de', 'opened again: still German');
    await p.shot('german.png');
    await p.press('L');
    await sleep(500);
    await p.close();

    // 6. a projector's scale, from the link
    p = await open(browser, '#projector&lesson=10_scan_line', 'projector');
    await p.shot('projector.png');
    await p.close();
  } finally {
    await browser.close();
  }
  if (failures.length) { console.log(`${failures.length} failed`); process.exit(1); }
  console.log('page_test: ok');
})().catch(e => { console.error(e); process.exit(1); });
