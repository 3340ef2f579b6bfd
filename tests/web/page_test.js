// SPDX-License-Identifier: MIT
// The page in a real browser: Debian's Chromium, headless, driven by puppeteer-core. Loads the built page from a
// local server and, on each page, checks that the console has no errors:
//   - the tour: it opens at step 0; → ← step; Space plays and pauses (read from the page's state line, #state);
//   - the same keys on lesson 01 in the page and in the desktop build (offscreen): the same state line and the same
//     hash of the events played; then N (the next lesson), X (practice) and an answer; the same for the lessons on
//     generated scenes;
//   - a link (#lesson=05_bsp_traversal&step=12) opens that lesson at that step, and the address follows the player;
//   - files of one's own: O's file picker and a drop on the window open a lesson with its scene; E offers the export
//     as downloads;
//   - the settings persist: the language chosen with L is the language after the page is opened again;
//   - the lesson menu (M), presets (P, a case, B), editing by mouse (a dragged end; S downloads the edited scene);
//   - long work shows its progress box, and Esc stops it;
//   - the keys a browser would take for itself (F1, F5, Ctrl+=) are the window's;
//   - devicePixelRatio 2: the same layout, sharp type;
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
              N: 'KeyN', X: 'KeyX', M: 'KeyM', P: 'KeyP', B: 'KeyB', S: 'KeyS', 7: 'Digit7',
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
    async until(question, pattern, ms = 20000) {  // the window's answer once it matches (a lesson opens over frames)
      const until = Date.now() + ms;
      for (let a = await p.ask(question); Date.now() < until; a = await p.ask(question)) {
        if (pattern.test(a)) return a;
        await sleep(50);
      }
      return await p.ask(question);
    },
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
    async drag(from, to) {  // the left button from one gesture point to another (as --keys' Drag: names them)
      const [ax, ay] = (await p.ask(`window_point ${from[0]} ${from[1]}`)).split(' ').map(Number);
      const [bx, by] = (await p.ask(`window_point ${to[0]} ${to[1]}`)).split(' ').map(Number);
      await page.mouse.move(ax, ay);
      await page.mouse.down();
      await page.mouse.move(bx, by, {steps: 8});
      await page.mouse.up();
      await page.evaluate(() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r))));
    },
    async downloads_into(folder) {
      fs.rmSync(folder, {recursive: true, force: true});
      const cdp = await page.target().createCDPSession();
      await cdp.send('Browser.setDownloadBehavior', {behavior: 'allow', downloadPath: folder});
    },
    async shot(file) { await page.screenshot({path: path.join(out, file)}); },
    expected: [],  // errors the test causes on purpose (patterns)
    async close() {
      const unexpected = errors.filter(e => !p.expected.some(pattern => pattern.test(e)));
      check(unexpected.length === 0, `${name}: no errors in the console` + (unexpected.length ? ': ' + unexpected.join(' | ') : ''));
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
    // the window's keys a browser would take for itself (F1 its help, F5 a reload, Ctrl+= its zoom) are the window's
    const taken = await p.page.evaluate(() => ['F1', 'F5', '=', '-', '0', 'F2'].map(key => {
      const e = new KeyboardEvent('keydown', {key, ctrlKey: key.length === 1, bubbles: true, cancelable: true});
      return key + (document.getElementById('canvas').dispatchEvent(e) ? ' browser' : ' window');
    }).join(', '));
    check(taken === 'F1 window, F5 window, = window, - window, 0 window, F2 browser', `keys kept from the browser: ${taken}`);
    const at = /^step \d+ of 64/.exec(await p.state())[0];
    await p.page.evaluate(() => { window.not_reloaded = true; });
    await p.press('F5');
    await sleep(300);
    check((await p.state()).startsWith(at + ', paused') && await p.page.evaluate(() => window.not_reloaded === true),
          `F5 reloads the lesson at its step, not the page: "${at}" → "${await p.state()}"`);
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
    const next = await p.until('lesson', /02_liang_barsky/);
    check(next.endsWith('/lessons/02_liang_barsky.toml'), `N: the next lesson (${next})`);
    await p.press('X');
    const exercise = await p.until('lesson', /practice/);
    check(/practice/.test(exercise), `X: an exercise (${exercise})`);
    await p.shot('practice.png');
    await p.press('Digit0', 'Period', 'Digit5', 'Enter');  // a typed number (Liang–Barsky asks for a t)
    await sleep(300);
    check(await p.ask('practice') === 'answered 1, right 0' || await p.ask('practice') === 'answered 1, right 1',
          `0.5 Enter answers it, and the score counts it: ${await p.ask('practice')}`);
    await p.close();

    // the lessons on generated scenes (a field, a city): the same scene, the same events in the page as on the desktop
    // (the generators draw portable random numbers: libc++'s distributions are not libstdc++'s)
    for (const lesson of ['22_culling_frustum', '23_culling_detail', '25_culling_hiz']) {
      const steps = ['Right', 'Right', 'Right'];
      p = await open(browser, '#lesson=' + lesson, lesson);
      await p.press(...steps);
      await sleep(300);
      const [state, trace] = [await p.state(), await p.ask('trace')];
      const desk = desktop_run(lesson, steps);
      check(state === desk.state && trace === desk.trace,
            `${lesson}: the page and the desktop play the same generated scene ("${state}" ${trace} | "${desk.state}" ${desk.trace})`);
      await p.close();
    }

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
    await p.downloads_into(downloads);
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
    check(await p.until('language', /^de$/) === 'de', 'L: German');
    await sleep(1000);  // IndexedDB is written after the settings file
    await p.close();
    p = await open(browser, '', 'the page opened again');
    check(await p.ask('language') === 'de', 'opened again: still German');
    await p.shot('german.png');
    await p.press('L');
    await sleep(500);
    await p.close();

    // 6. the lesson menu: M opens it on the lesson playing; ↓ ↓ and Enter open the second lesson after it
    p = await open(browser, '', 'the lesson menu');
    await p.press('M');
    check(/lesson menu open/.test(await p.waitFor(/lesson menu open/)), `M: the lesson menu opens ("${await p.state()}")`);
    await p.shot('menu.png');
    await p.press('ArrowDown', 'ArrowDown', 'Enter');
    const chosen = await p.until('lesson', /02_liang_barsky/);
    const start = await p.waitFor(/^step 0 of 42/);
    check(chosen.endsWith('/lessons/02_liang_barsky.toml') && /^step 0 of 42, paused, score/.test(start),
          `↓ ↓ Enter: the second lesson after the tour, from its start, the menu closed (${chosen}: "${start}")`);
    await p.close();

    // 7. presets: P lists the extreme cases; 7 plays the seventh with the lesson's algorithm; B goes back
    p = await open(browser, '#lesson=13_depth_sort_cycle', 'presets');
    await p.press('P');
    await p.shot('presets.png');
    await p.press('7');
    const preset = await p.until('lesson', /extreme/);
    check(preset.endsWith('/extreme/depth_sort_cyclic_overlap.toml'), `P 7: the cyclic overlap plays (${preset})`);
    await p.press('B');
    const back = await p.until('lesson', /lessons/);
    check(back.endsWith('/lessons/13_depth_sort_cycle.toml'), `B: back to the lesson (${back})`);
    await p.close();

    // 8. editing by mouse: drag segment 1's end from (4, 1) to (4, -2) in the BSP plan; the machine reruns; S downloads
    //    the edited scene with the end where it was dropped
    p = await open(browser, '#lesson=04_bsp_build', 'editing by mouse');
    await p.press('Right');
    const before = await p.waitFor(/^step 1 of/);
    await p.drag([4, 1], [4, -2]);
    const after = await p.waitFor(/^step 1 of (?!41\b)/, 5000);
    check(/^step 1 of \d+/.test(after) && after.split(',')[0] !== before.split(',')[0],
          `a dragged end: the machine reran, the cursor kept ("${before}" → "${after}")`);
    await p.shot('edited.png');
    const edited = path.join(out, 'edited');
    await p.downloads_into(edited);
    await p.press('S');
    const saved = path.join(edited, '04_bsp_build-edited.toml');
    for (let k = 0; k < 50 && !fs.existsSync(saved); ++k) await sleep(100);
    const text = fs.existsSync(saved) ? fs.readFileSync(saved, 'utf8') : '';
    check(/b = \[ (4\.0[01]|3\.9[89])[0-9]*, -(1\.9[89]|2\.0[01])[0-9]*, 0\.0 \]/.test(text),
          `S: the edited scene is downloaded with the end at (4, -2) to within a pixel (${fs.existsSync(saved) ? 'downloaded' : 'no download'})`);
    await p.close();

    // 9. long work: a dropped lesson on a 200,000-triangle city takes tens of seconds to open; the page shows the
    //    progress box while it works (not a frozen tab), and Esc stops it, said instead of the scene
    p = await open(browser, '', 'long work');
    p.expected.push(/opening \/uploads\/huge\.toml was stopped \(Esc\)/);
    await p.page.evaluate(() => {
      const files = new DataTransfer();
      files.items.add(new File(['title = "A huge city"\nalgorithm = "bsp_traversal"\nscene = "city:200000"\n'], 'huge.toml'));
      document.getElementById('canvas').dispatchEvent(new DragEvent('drop', {dataTransfer: files, bubbles: true, cancelable: true}));
    });
    const working = await p.waitFor(/^working: opening huge\.toml: [0-9,]+ machine steps/, 10000);
    check(/^working: opening huge\.toml/.test(working), `the page shows its long work: "${working}"`);
    let later = working;
    for (let k = 0; k < 60 && later === working; ++k) await sleep(50), later = await p.state();
    check(/^working: opening huge\.toml/.test(later) && later !== working, `and it goes on showing it: "${later}"`);
    await p.shot('working.png');
    await p.press('Escape');
    for (let k = 0; k < 50 && !/stopped/.test(await p.ask('error')); ++k) await sleep(100);
    check(/^opening \/uploads\/huge\.toml was stopped \(Esc\) after/.test(await p.ask('error')), `Esc stops it: "${await p.ask('error')}"`);
    await p.shot('stopped.png');
    await p.close();

    // 10. a high-density screen (devicePixelRatio 2, as a laptop's): the same layout in CSS pixels as at 1, with the
    //     type rasterised for the device's pixels (it was laid out twice too big, the bottom bar cut)
    const dense = await browser.newPage();
    await dense.setViewport({width: 1280, height: 800, deviceScaleFactor: 2});
    await dense.goto(url + '#lesson=04_bsp_build');
    await dense.waitForFunction(() => /^step \d+ of/.test(document.getElementById('state').textContent), {timeout: 30000});
    await sleep(300);
    const dense_ask = q => dense.evaluate(q => Module.ccall('hsr_query', 'string', ['string'], [q]), q);
    const canvas = await dense.evaluate(() => { const c = document.getElementById('canvas'); return `${c.width}x${c.height}`; });
    check(canvas === '2560x1600' && await dense_ask('type_size') === '17' && await dense_ask('layout') === '',
          `devicePixelRatio 2: a 2560×1600 canvas, type 17 points as at 1, nothing cut (${canvas}, ${await dense_ask('type_size')}, "${await dense_ask('layout')}")`);
    await dense.screenshot({path: path.join(out, 'dense.png')});
    await dense.close();

    // 11. a projector's scale, from the link
    p = await open(browser, '#projector&lesson=10_scan_line', 'projector');
    await p.shot('projector.png');
    await p.close();
  } finally {
    await browser.close();
  }
  if (failures.length) { console.log(`${failures.length} failed`); process.exit(1); }
  console.log('page_test: ok');
})().catch(e => { console.error(e); process.exit(1); });
