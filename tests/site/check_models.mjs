// The models of the chapter pages (tools/site/models.js), in headless Chromium:
//  - every chapter whose program takes --model draws the site's house (tests/models/),
//    each of its model figures byte for byte as the native program draws it with
//    --model tests/models/house.obj, and the address names the model;
//  - the house's three files chosen with the page's file picker draw the same, and a
//    figure asked for while another is being drawn (the worker ended and made anew)
//    is still the model's;
//  - files the program refuses, chosen with the picker: the page shows the very line the
//    native program prints, and keeps the figures it had; the .obj alone: the program's
//    warnings about its library, and the model drawn without it;
//  - "none" brings back the chapter's own figures (its first equals its golden image);
//  - where Debian's assimp-testmodels is installed, the spider in chapter 14 (its JPEG
//    textures decoded by the browser) and the Wuson in chapter 5, from a moved camera,
//    equal what the native programs draw.
// Usage: node check_models.mjs REPO SITE NATIVE_BUILD
// Exit status 0 when all passed, 1 when one failed (each failure is one line).
import { spawnSync } from "node:child_process";
import {
  copyFileSync,
  existsSync,
  mkdirSync,
  mkdtempSync,
  readdirSync,
  rmSync,
  writeFileSync,
} from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { Browser, fail, failureCount } from "./browser.mjs";
import { pngDigest } from "./png.mjs";

const [repo, site, native] = process.argv.slice(2, 5).map((p) => resolve(p));
const house = join(repo, "tests", "models");
const assimp = "/usr/share/assimp/models/OBJ";
const work = mkdtempSync(join(tmpdir(), "cgfs-site-models-"));

const kDrawn = "document.getElementById('canvas').dataset.drawn === 'full'";
// The chapter's parameters as controls (chapter.js's setUpControls), where it has them, shown.
const kControlsShown = "document.getElementById('controls')?.hidden === false";
const kSaid =
  "document.getElementById('model-said').hidden ? '' : document.getElementById('model-said').textContent";
const kFigureNames =
  "Array.from(document.querySelectorAll('#figure-lists button'), (b) => b.textContent)";

const sameJson = (a, b) => JSON.stringify(a) === JSON.stringify(b);

// The native program's images of the model (in a folder of their own, by figure name),
// and what it printed on its standard error.
function drawNatively(chapter, model, more = []) {
  const out = mkdtempSync(join(work, "native-"));
  const run = spawnSync(join(native, chapter), ["--model", model, "--output", out, ...more], {
    encoding: "utf8",
  });
  return { out, status: run.status, stderr: run.stderr.trimEnd() };
}

async function showFigure(browser, index) {
  await browser.evaluate(`(() => { delete document.getElementById('canvas').dataset.drawn;
    document.querySelectorAll('#figure-lists button')[${index}].click(); })()`);
  return browser.waitFor(kDrawn, `figure ${index} drawn`);
}

// Every figure the page lists now equals the native program's image of the same name.
async function compareFigures(browser, chapter, images, what) {
  const names = await browser.evaluate(kFigureNames);
  const expected = readdirSync(images)
    .filter((f) => f.endsWith(".png"))
    .map((f) => f.slice(0, -4))
    .sort();
  if (!sameJson([...names].sort(), expected))
    fail(`${chapter} ${what}: the page lists ${names}, the program draws ${expected}`);
  for (const [index, name] of names.entries()) {
    await showFigure(browser, index);
    if (!sameJson(await browser.canvasDigest(), pngDigest(join(images, `${name}.png`)))) {
      fail(`${chapter} ${what}: ${name} differs from the native program's`);
    }
  }
  return names.length;
}

async function checkSiteHouse(browser, chapter) {
  await browser.open(`${chapter}/index.html?model=house`);
  await browser.waitFor(kDrawn, `${chapter}: the house drawn`);
  const drawnNatively = drawNatively(chapter, join(house, "house.obj"));
  const compared = await compareFigures(browser, chapter, drawnNatively.out, "the site's house");
  if (await browser.evaluate(kControlsShown))
    fail(`${chapter}: the chapter's controls are shown beside the model's figures`);
  const address = await browser.evaluate("location.search");
  if (!address.startsWith("?model=house&figure="))
    fail(`${chapter}: the address is ${address}, without the model`);
  console.log(`${chapter}: the site's house, ${compared} figures, as the program draws them`);
}

// The picker: the house's own files; a refused file; the .obj alone; back to none.
async function checkPicker(browser, chapter) {
  await browser.open(`${chapter}/index.html`);
  await browser.waitFor(kDrawn, `${chapter}: the first figure`);
  const own = (await browser.evaluate(kFigureNames))[0];
  const kOwnFirst = `document.querySelector('#figure-lists button')?.textContent === ${JSON.stringify(own)}`;
  await browser.chooseFiles(
    "#model-files",
    ["house.obj", "house.mtl", "house-bricks.ppm"].map((f) => join(house, f)),
  );
  await browser.waitFor(`${kDrawn} && !(${kOwnFirst})`, `${chapter}: the chosen house drawn`);
  const drawnNatively = drawNatively(chapter, join(house, "house.obj"));
  // The worker ended and made anew, as when a figure is asked for while another is drawn:
  // the new one is given the model too.
  await browser.evaluate(`(() => { figuresWorker.restart(); delete document.getElementById('canvas').dataset.drawn;
    document.querySelectorAll('#figure-lists button')[0].click(); })()`);
  await browser.waitFor(kDrawn, `${chapter}: the model after a restart`);
  const first = (await browser.evaluate(kFigureNames))[0];
  if (!sameJson(await browser.canvasDigest(), pngDigest(join(drawnNatively.out, `${first}.png`)))) {
    fail(`${chapter}: the chosen house's ${first} differs from the native program's`);
  }

  const bad = join(work, "index-zero.obj");
  writeFileSync(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  const refused = drawNatively(chapter, bad);
  await browser.chooseFiles("#model-files", [bad]);
  await browser.waitFor(`(${kSaid}).includes('error')`, `${chapter}: the refusal said`, 20);
  const said = await browser.evaluate(kSaid);
  if (refused.status !== 2 || said !== refused.stderr.replaceAll(bad, "index-zero.obj")) {
    fail(
      `${chapter}: for index-zero.obj the page says "${said}", the program (exit ${refused.status}) "${refused.stderr}"`,
    );
  }
  if ((await browser.evaluate(kFigureNames))[0] !== first)
    fail(`${chapter}: a refused file changed the figures`);
  // The list still names the model drawn, and the line is in view (it is below the picture).
  const listed = await browser.evaluate(
    "document.getElementById('model-choice').selectedOptions[0].textContent",
  );
  if (listed !== "your own: house.obj")
    fail(`${chapter}: after a refused file the list says "${listed}", not the house still drawn`);
  // (within a pixel: layout places it in fractions of one)
  const inView = await browser.evaluate(
    `(({top, bottom}) => top >= 0 && bottom <= innerHeight + 1)` +
      `(document.getElementById('model-said').getBoundingClientRect())`,
  );
  if (!inView) fail(`${chapter}: the refusal's line is out of view`);

  const alone = join(work, "alone");
  rmSync(alone, { recursive: true, force: true });
  mkdirSync(alone, { recursive: true });
  copyFileSync(join(house, "house.obj"), join(alone, "house.obj"));
  const warned = spawnSync(
    join(native, chapter),
    ["--model", "house.obj", "--figure", "model", "--output", join(work, "alone-out")],
    { cwd: alone, encoding: "utf8" },
  );
  await browser.chooseFiles("#model-files", [join(alone, "house.obj")]);
  await browser.waitFor(
    `(${kSaid}).includes('warning') && ${kDrawn}`,
    `${chapter}: the .obj alone drawn`,
    20,
  );
  const warnings = await browser.evaluate(kSaid);
  if (warnings !== warned.stderr.trimEnd())
    fail(
      `${chapter}: for house.obj alone the page says "${warnings}", the program "${warned.stderr.trimEnd()}"`,
    );

  await browser.evaluate(`(() => { const select = document.getElementById('model-choice'); select.value = '';
    select.dispatchEvent(new Event('change')); })()`);
  await browser.waitFor(`${kDrawn} && ${kOwnFirst}`, `${chapter}: the chapter's figures again`);
  if (await browser.evaluate(`!!document.getElementById('controls') && !(${kControlsShown})`))
    fail(`${chapter}: back to none, the chapter's controls stay hidden`);
  await showFigure(browser, 0);
  if (
    !sameJson(
      await browser.canvasDigest(),
      pngDigest(join(repo, "tests", "golden", chapter, `${own}.png`)),
    )
  ) {
    fail(`${chapter}: back to none, ${own} differs from its golden image`);
  }
  console.log(
    `${chapter}: the picker's house as the program draws it, after a restart too; ` +
      `"${said}"; the .obj alone warned as the program warns; none: the chapter's ${own} again`,
  );
}

// An assimp model from a moved camera, as in the deep tier's corpus check.
async function checkAssimp(browser, chapter, name) {
  const view = "2.2,0.5,1.2,51,-10";
  await browser.open(`${chapter}/index.html?model=${name}&figure=model&view=${view}`);
  await browser.waitFor(kDrawn, `${chapter}: ${name} drawn`, 120);
  const drawnNatively = drawNatively(chapter, join(assimp, `${name}.obj`), [
    "--figure",
    "model",
    "--view",
    view,
  ]);
  if (!sameJson(await browser.canvasDigest(), pngDigest(join(drawnNatively.out, "model.png")))) {
    fail(`${chapter}: ${name} from ${view} differs from the native program's`);
  } else {
    console.log(`${chapter}: ${name} from ${view}, as the program draws it`);
  }
}

const browser = await Browser.open(site);
try {
  const chapters = readdirSync(join(repo, "chapters"))
    .filter((c) => /^\d\d-/.test(c))
    .sort()
    .filter(
      (c) =>
        existsSync(join(site, c, "index.html")) &&
        existsSync(join(repo, "chapters", c, "options.cpp")),
    )
    .filter((c) =>
      spawnSync(join(native, c), ["--help"], { encoding: "utf8" }).stdout.includes("--model"),
    );
  if (chapters.length < 8) fail(`only ${chapters.length} chapters take --model: ${chapters}`);
  for (const chapter of chapters) await checkSiteHouse(browser, chapter);
  await checkPicker(browser, "14-textures");
  await checkPicker(browser, "05-raytracer-extensions");
  if (existsSync(join(assimp, "spider.obj"))) {
    await checkAssimp(browser, "14-textures", "spider");
    await checkAssimp(browser, "05-raytracer-extensions", "WusonOBJ");
  } else {
    console.log(
      `no ${assimp}: the spider and the Wuson not checked (scripts/setup --deep installs them)`,
    );
  }
} finally {
  await browser.close();
  rmSync(work, { recursive: true, force: true });
}
if (browser.outside.length)
  fail(
    `the pages asked for what is not on this machine: ${[...new Set(browser.outside)].join(", ")}`,
  );
console.log(failureCount() === 0 ? "PASS: the models of the site" : `${failureCount()} failed`);
process.exit(failureCount() === 0 ? 0 : 1);
