// The site of scripts/site, in headless Chromium, driven through its DevTools protocol:
//  - every figure of every chapter, drawn through the page's own buttons, equals its
//    golden image byte for byte (the canvas read back);
//  - on the pages of chapters 5 and 15, keys and a mouse drag move the camera: the
//    frame is drawn at half size while it moves, the view shown after three keys is
//    the one worked by hand, and the full frame after the drag equals what the native
//    program draws with --view set to the view the page shows;
//  - on chapter 5's page, C and the button beside the caption switch between a figure
//    and its cost view; a cost view of 3.6 billion tests says the count the native
//    program says (every count is 64-bit, in WebAssembly too); the lists say how many
//    figures they hold;
//  - a page asked for a figure or a view that does not exist says so and draws the
//    chapter's first figure; the index draws a picture for every chapter;
//  - every link of every page leads to a file of the site.
// With --speed CHAPTER:FIGURE ..., it only times those figures instead: the page's
// first draw and the best of 15, and the best of 5 runs of the native program on one
// thread. With
// --screenshot PAGE WIDTHxHEIGHT FILE, it saves a PNG of the page once it is drawn.
//
// Usage: node check_site.mjs REPO SITE NATIVE_BUILD
//            [--speed CHAPTER:FIGURE ... | --screenshot PAGE WIDTHxHEIGHT FILE]
// Exit status 0 when all passed, 1 when one failed (each failure is one line).
import { execFileSync } from "node:child_process";
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, dirname, resolve } from "node:path";
import { Browser, fail, failureCount, sleep } from "./browser.mjs";
import { pngDigest } from "./png.mjs";

const [repo, site, native] = process.argv.slice(2, 5).map((p) => resolve(p));
const speedIndex = process.argv.indexOf("--speed");

const sameJson = (a, b) => JSON.stringify(a) === JSON.stringify(b);
const allChapters = () =>
  readdirSync(join(repo, "chapters"))
    .filter((name) => /^\d\d-/.test(name))
    .sort();

// Clicks figure `index`'s button and waits for its full frame.
async function showFigure(browser, index) {
  await browser.evaluate(`(() => { const canvas = document.getElementById('canvas');
    delete canvas.dataset.drawn; document.querySelectorAll('#figure-lists button')[${index}].click(); })()`);
  return browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `figure ${index} drawn`,
  );
}

async function checkEveryFigure(browser) {
  let compared = 0;
  for (const chapter of allChapters()) {
    if (!(await browser.open(`${chapter}/index.html`))) continue;
    const names = await browser.evaluate(
      "Array.from(document.querySelectorAll('#figure-lists button'), (b) => b.textContent)",
    );
    for (const [index, name] of names.entries()) {
      await showFigure(browser, index);
      const problem = await browser.evaluate("document.getElementById('problem').textContent");
      const golden = join(repo, "tests", "golden", chapter, `${name}.png`);
      if (problem) fail(`${chapter}/${name}: the page says "${problem}"`);
      else if (!sameJson(await browser.canvasDigest(), pngDigest(golden))) {
        fail(`${chapter}/${name}: the canvas differs from ${golden}`);
      }
      ++compared;
    }
  }
  console.log(
    `every figure, drawn through the page's buttons, compared with its golden image: ${compared}`,
  );
}

// The C key, and the button beside the caption, switch between a figure and its cost view.
async function checkCostKey(browser, chapter, figure, costView) {
  await browser.open(`${chapter}/index.html?figure=${figure}`);
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: ${figure}`,
  );
  const button = await browser.evaluate("document.getElementById('cost').textContent");
  if (button !== `where the work goes: ${costView} (C)`)
    fail(`${chapter}: ${figure}'s cost button says '${button}'`);
  await browser.evaluate(
    "(() => { delete document.getElementById('canvas').dataset.drawn; document.body.focus(); })()",
  );
  await browser.key("c");
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: C`,
  );
  if (
    !sameJson(
      await browser.canvasDigest(),
      pngDigest(join(repo, "tests", "golden", chapter, `${costView}.png`)),
    )
  ) {
    fail(`${chapter}: C on ${figure} did not show ${costView}`);
  }
  const back = await browser.evaluate("document.getElementById('cost').textContent");
  if (back !== `back to ${figure} (C)`)
    fail(`${chapter}: ${costView}'s cost button says '${back}'`);
  await browser.evaluate(
    "(() => { delete document.getElementById('canvas').dataset.drawn; document.getElementById('cost').click(); })()",
  );
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: the cost button`,
  );
  if (
    !sameJson(
      await browser.canvasDigest(),
      pngDigest(join(repo, "tests", "golden", chapter, `${figure}.png`)),
    )
  ) {
    fail(`${chapter}: the cost button on ${costView} did not go back to ${figure}`);
  }
  console.log(`${chapter}: C showed ${costView}, its button ${figure} again`);
}

// A count past 2^31 on the page, as the native program prints it: the status line ends
// with what the figure measured ("3 600 360 000 in all, at most 10 001").
async function checkLargeCount(browser, chapter, figure) {
  await browser.open(`${chapter}/index.html?figure=${figure}`);
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: ${figure}`,
  );
  const status = await browser.evaluate("document.getElementById('status').textContent");
  const out = mkdtempSync(join(tmpdir(), "cgfs-count-"));
  const wrote = execFileSync(join(native, chapter), ["--figure", figure, "--output", out], {
    encoding: "utf8",
  });
  rmSync(out, { recursive: true });
  const measured = wrote.trim().split(": ").pop();
  if (!status.endsWith(`; ${measured}`))
    fail(`${chapter}: ${figure} says '${status}', the program '${measured}'`);
  else console.log(`${chapter}: ${figure} counts as the program does: ${measured}`);
  // The lists say how many figures they hold (they show three rows, and scroll).
  const [count, figures, views] =
    await browser.evaluate(`[document.getElementById('figures-count').textContent,
    document.querySelectorAll('#figures button').length, document.querySelectorAll('#cost-views button').length]`);
  const listed = `${figures} figures and ${views} views of where the work goes: the list scrolls`;
  if (count !== listed) fail(`${chapter}: the lists say '${count}', not '${listed}'`);
}

async function checkCamera(browser, chapter, figure) {
  await browser.open(`${chapter}/index.html?figure=${figure}`);
  // The page's first frame is drawn after it loads: waited for, or it could land after
  // the keys below and be taken for a frame of the moving camera.
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: the first frame`,
  );
  await browser.evaluate("document.body.focus()");
  // Every frame drawn from here on, in order (a frame's mark can be cleared by the next
  // draw before it is read: the first is kept, however fast they come).
  await browser.evaluate(`(() => { const canvas = document.getElementById('canvas'); delete canvas.dataset.drawn;
    window.__frames = []; new MutationObserver(() => { if (canvas.dataset.drawn) window.__frames.push(canvas.dataset.drawn); })
      .observe(canvas, {attributes: true, attributeFilter: ['data-drawn']}); })()`);
  for (const key of ["ArrowUp", "ArrowUp", "q"]) await browser.key(key);
  // The frames come from the page's worker: the first after the keys, at half size.
  await browser.waitFor("window.__frames.length > 0", `${chapter}: a frame after the keys`, 10);
  const drawn = await browser.evaluate("window.__frames[0]");
  if (drawn !== "preview")
    fail(`${chapter}: the frame while the camera moves is drawn '${drawn}', not at half size`);
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: the settled frame after the keys`,
  );
  const walked = await browser.evaluate("document.getElementById('view').textContent");
  // Forward a quarter unit twice, turned 5 degrees left once (program/camera_controls.h).
  if (walked !== "0,0,0.5,5,0")
    fail(`${chapter}: after Up, Up, Q the page shows the view ${walked}, not 0,0,0.5,5,0`);
  const box = await browser.evaluate(
    "(({x, y, width, height}) => [x, y, width, height])" +
      "(document.getElementById('canvas').getBoundingClientRect())",
  );
  await browser.drag(box[0] + box[2] / 2, box[1] + box[3] / 2, 40, -24);
  await sleep(400);
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: the settled frame`,
  );
  const view = await browser.evaluate("document.getElementById('view').textContent");
  if (view === walked) fail(`${chapter}: dragging the picture did not turn the camera`);
  const out = mkdtempSync(join(tmpdir(), "cgfs-view-"));
  execFileSync(join(native, chapter), ["--figure", figure, "--view", view, "--output", out], {
    stdio: "ignore",
  });
  const same = sameJson(await browser.canvasDigest(), pngDigest(join(out, `${figure}.png`)));
  rmSync(out, { recursive: true });
  if (!same)
    fail(`${chapter}: the page's frame at view ${view} differs from ${chapter} --view ${view}`);
  const link = await browser.evaluate("document.getElementById('view-link').getAttribute('href')");
  if (link !== `?figure=${figure}&view=${encodeURIComponent(view)}`)
    fail(`${chapter}: the view's link is ${link}`);
  console.log(
    `${chapter}: keys and a drag walked ${figure} to ${view}; the native program draws the same frame`,
  );
}

async function checkBadAddresses(browser) {
  const cases = [
    ["02-basic-rays/index.html?figure=fig-9-99", 'This chapter has no figure "fig-9-99"'],
    ["05-raytracer-extensions/index.html?figure=fig-5-1-camera&view=1,2", 'No view "1,2"'],
    ["02-basic-rays/index.html?figure=fig-2-11&view=0,0,1,0,0", "fig-2-11 has no camera to move"],
  ];
  for (const [page, said] of cases) {
    await browser.open(page);
    await browser.waitFor(
      "document.getElementById('canvas').dataset.drawn === 'full'",
      `${page} draws`,
    );
    const problem = await browser.evaluate(
      "document.getElementById('problem').hidden ? '' : " +
        "document.getElementById('problem').textContent",
    );
    if (!problem.startsWith(said)) fail(`${page}: the page says "${problem}", not "${said}…"`);
    else console.log(`${page}: "${problem}"`);
  }
}

async function checkIndex(browser) {
  await browser.open("index.html");
  await browser.waitFor(
    "document.body.dataset.thumbnails === 'drawn'",
    "the index draws its pictures",
    120,
  );
  const blank =
    await browser.evaluate(`Array.from(document.querySelectorAll('canvas.thumbnail')).filter((c) => {
    const p = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    return p.every((v, i) => v === p[i % 4]); }).map((c) => c.dataset.chapter)`);
  const count = await browser.evaluate("document.querySelectorAll('canvas.thumbnail').length");
  if (count !== allChapters().length)
    fail(`the index has ${count} pictures for ${allChapters().length} chapters`);
  if (blank.length) fail(`the index's pictures of ${blank.join(", ")} are blank`);
  console.log(`the index drew ${count} pictures`);
}

// Every href and src of every page of the site leads to a file of the site.
function checkLinks() {
  let links = 0;
  const pages = readdirSync(site, { recursive: true }).filter((path) => path.endsWith(".html"));
  for (const page of pages) {
    const text = readFileSync(join(site, page), "utf8");
    for (const [, target] of text.matchAll(/(?:href|src)="([^"#?]+)[^"]*"/g)) {
      if (/^[a-z]+:/.test(target)) continue;
      ++links;
      if (!existsSync(join(dirname(join(site, page)), target.replaceAll("&amp;", "&")))) {
        fail(`${page} links to ${target}, which the site does not have`);
      }
    }
  }
  console.log(`${links} links in ${pages.length} pages, each to a file of the site`);
}

// Milliseconds of a figure: on its page its first draw after the page opened (the
// WebAssembly not yet optimised by the browser) and the best of 15, natively the best of
// 5 runs on one thread (the time the program prints).
async function speed(browser, chapter, figure) {
  await browser.open(`${chapter}/index.html?figure=${figure}`);
  await browser.waitFor(
    "document.getElementById('canvas').dataset.drawn === 'full'",
    `${chapter}: ${figure}`,
    120,
  );
  const first = Number(
    await browser.evaluate("document.getElementById('canvas').dataset.milliseconds"),
  );
  const index = await browser.evaluate(
    `Array.from(document.querySelectorAll('#figure-lists button'), (b) => b.textContent).indexOf('${figure}')`,
  );
  const page = [];
  for (let i = 0; i < 15; ++i) {
    await showFigure(browser, index);
    page.push(
      Number(await browser.evaluate("document.getElementById('canvas').dataset.milliseconds")),
    );
  }
  const threads = ["05", "16", "17"].includes(chapter.slice(0, 2)) ? ["--threads", "1"] : [];
  const runs = [];
  for (let i = 0; i < 5; ++i) {
    const out = mkdtempSync(join(tmpdir(), "cgfs-speed-"));
    const printed = execFileSync(join(native, chapter), [
      "--figure",
      figure,
      "--output",
      out,
      ...threads,
    ]).toString();
    rmSync(out, { recursive: true });
    runs.push(Number(/rendered in ([\d.]+) ms/.exec(printed)[1]));
  }
  const [inPage, natively] = [Math.min(...page), Math.min(...runs)];
  const ms = (value) =>
    `${value < 10 ? value.toFixed(1) : Math.round(value).toLocaleString("en").replaceAll(",", " ")} ms`;
  console.log(
    `| ${chapter.slice(0, 2)} | \`${figure}\` | ${ms(natively)} | ${ms(first)} | ${ms(inPage)} | ` +
      `${(inPage / natively).toFixed(2)} |`,
  );
}

// A picture of a page (its address relative to the site) once its figures are drawn.
async function screenshot(browser, page, size, file) {
  const [width, height] = size.split("x").map(Number);
  await browser.send("Emulation.setDeviceMetricsOverride", {
    width,
    height,
    deviceScaleFactor: 1,
    mobile: false,
  });
  await browser.open(page);
  await browser.waitFor(
    "document.getElementById('canvas')?.dataset.drawn === 'full' || " +
      "document.body.dataset.thumbnails === 'drawn'",
    `${page} drawn`,
    120,
  );
  const { data } = await browser.send("Page.captureScreenshot", { format: "png" });
  writeFileSync(file, Buffer.from(data, "base64"));
  console.log(`wrote ${file}`);
}

const browser = await Browser.open(site);
const screenshotIndex = process.argv.indexOf("--screenshot");
try {
  if (screenshotIndex > 0) {
    await screenshot(browser, ...process.argv.slice(screenshotIndex + 1, screenshotIndex + 4));
  } else if (speedIndex > 0) {
    for (const item of process.argv.slice(speedIndex + 1)) await speed(browser, ...item.split(":"));
  } else {
    checkLinks();
    await checkBadAddresses(browser);
    await checkCamera(browser, "05-raytracer-extensions", "fig-5-1-camera");
    await checkCostKey(
      browser,
      "05-raytracer-extensions",
      "subsampling-thin-wires",
      "subsampling-thin-wires-searches",
    );
    await checkLargeCount(
      browser,
      "05-raytracer-extensions",
      "sphere-field-10000-tests-without-hierarchy",
    );
    await checkCamera(browser, "15-rasterizer-extensions", "everything");
    await checkIndex(browser);
    await checkEveryFigure(browser);
  }
} finally {
  await browser.close();
}
if (browser.outside.length)
  fail(
    `the pages asked for what is not on this machine: ${[...new Set(browser.outside)].join(", ")}`,
  );
console.log(failureCount() === 0 ? "PASS: the site" : `${failureCount()} failed`);
process.exit(failureCount() === 0 ? 0 : 1);
