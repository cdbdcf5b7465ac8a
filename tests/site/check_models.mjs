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
import { Browser, Fail, Failures } from "./browser.mjs";
import { PngDigest } from "./png.mjs";

const [repo, site, native] = process.argv.slice(2, 5).map((p) => resolve(p));
const house = join(repo, "tests", "models");
const assimp = "/usr/share/assimp/models/OBJ";
const work = mkdtempSync(join(tmpdir(), "cgfs-site-models-"));

const kDrawn = "document.getElementById('canvas').dataset.drawn === 'full'";
// The chapter's parameters as controls (chapter.js's Controls), where it has them, shown.
const kControlsShown = "document.getElementById('controls')?.hidden === false";
const kSaid =
  "document.getElementById('model-said').hidden ? '' : document.getElementById('model-said').textContent";
const kFigureNames =
  "Array.from(document.querySelectorAll('#figure-lists button'), (b) => b.textContent)";

const Same = (a, b) => JSON.stringify(a) === JSON.stringify(b);

// The native program's images of the model (in a folder of their own, by figure name),
// and what it printed on its standard error.
function Native(chapter, model, more = []) {
  const out = mkdtempSync(join(work, "native-"));
  const run = spawnSync(join(native, chapter), ["--model", model, "--output", out, ...more], {
    encoding: "utf8",
  });
  return { out, status: run.status, stderr: run.stderr.trimEnd() };
}

async function ShowFigure(browser, index) {
  await browser.Evaluate(`(() => { delete document.getElementById('canvas').dataset.drawn;
    document.querySelectorAll('#figure-lists button')[${index}].click(); })()`);
  return browser.WaitFor(kDrawn, `figure ${index} drawn`);
}

// Every figure the page lists now equals the native program's image of the same name.
async function CompareFigures(browser, chapter, images, what) {
  const names = await browser.Evaluate(kFigureNames);
  const expected = readdirSync(images)
    .filter((f) => f.endsWith(".png"))
    .map((f) => f.slice(0, -4))
    .sort();
  if (!Same([...names].sort(), expected))
    Fail(`${chapter} ${what}: the page lists ${names}, the program draws ${expected}`);
  for (const [index, name] of names.entries()) {
    await ShowFigure(browser, index);
    if (!Same(await browser.CanvasDigest(), PngDigest(join(images, `${name}.png`)))) {
      Fail(`${chapter} ${what}: ${name} differs from the native program's`);
    }
  }
  return names.length;
}

async function CheckSiteHouse(browser, chapter) {
  await browser.Open(`${chapter}/index.html?model=house`);
  await browser.WaitFor(kDrawn, `${chapter}: the house drawn`);
  const drawnNatively = Native(chapter, join(house, "house.obj"));
  const compared = await CompareFigures(browser, chapter, drawnNatively.out, "the site's house");
  if (await browser.Evaluate(kControlsShown))
    Fail(`${chapter}: the chapter's controls are shown beside the model's figures`);
  const address = await browser.Evaluate("location.search");
  if (!address.startsWith("?model=house&figure="))
    Fail(`${chapter}: the address is ${address}, without the model`);
  console.log(`${chapter}: the site's house, ${compared} figures, as the program draws them`);
}

// The picker: the house's own files; a refused file; the .obj alone; back to none.
async function CheckPicker(browser, chapter) {
  await browser.Open(`${chapter}/index.html`);
  await browser.WaitFor(kDrawn, `${chapter}: the first figure`);
  const own = (await browser.Evaluate(kFigureNames))[0];
  const kOwnFirst = `document.querySelector('#figure-lists button')?.textContent === ${JSON.stringify(own)}`;
  await browser.ChooseFiles(
    "#model-files",
    ["house.obj", "house.mtl", "house-bricks.ppm"].map((f) => join(house, f)),
  );
  await browser.WaitFor(`${kDrawn} && !(${kOwnFirst})`, `${chapter}: the chosen house drawn`);
  const drawnNatively = Native(chapter, join(house, "house.obj"));
  // The worker ended and made anew, as when a figure is asked for while another is drawn:
  // the new one is given the model too.
  await browser.Evaluate(`(() => { figuresWorker.Restart(); delete document.getElementById('canvas').dataset.drawn;
    document.querySelectorAll('#figure-lists button')[0].click(); })()`);
  await browser.WaitFor(kDrawn, `${chapter}: the model after a restart`);
  const first = (await browser.Evaluate(kFigureNames))[0];
  if (!Same(await browser.CanvasDigest(), PngDigest(join(drawnNatively.out, `${first}.png`)))) {
    Fail(`${chapter}: the chosen house's ${first} differs from the native program's`);
  }

  const bad = join(work, "index-zero.obj");
  writeFileSync(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  const refused = Native(chapter, bad);
  await browser.ChooseFiles("#model-files", [bad]);
  await browser.WaitFor(`(${kSaid}).includes('error')`, `${chapter}: the refusal said`, 20);
  const said = await browser.Evaluate(kSaid);
  if (refused.status !== 2 || said !== refused.stderr.replaceAll(bad, "index-zero.obj")) {
    Fail(
      `${chapter}: for index-zero.obj the page says "${said}", the program (exit ${refused.status}) "${refused.stderr}"`,
    );
  }
  if ((await browser.Evaluate(kFigureNames))[0] !== first)
    Fail(`${chapter}: a refused file changed the figures`);
  // The list still names the model drawn, and the line is in view (it is below the picture).
  const listed = await browser.Evaluate(
    "document.getElementById('model-choice').selectedOptions[0].textContent",
  );
  if (listed !== "your own: house.obj")
    Fail(`${chapter}: after a refused file the list says "${listed}", not the house still drawn`);
  // (within a pixel: layout places it in fractions of one)
  const inView = await browser.Evaluate(
    `(({top, bottom}) => top >= 0 && bottom <= innerHeight + 1)` +
      `(document.getElementById('model-said').getBoundingClientRect())`,
  );
  if (!inView) Fail(`${chapter}: the refusal's line is out of view`);

  const alone = join(work, "alone");
  rmSync(alone, { recursive: true, force: true });
  mkdirSync(alone, { recursive: true });
  copyFileSync(join(house, "house.obj"), join(alone, "house.obj"));
  const warned = spawnSync(
    join(native, chapter),
    ["--model", "house.obj", "--figure", "model", "--output", join(work, "alone-out")],
    { cwd: alone, encoding: "utf8" },
  );
  await browser.ChooseFiles("#model-files", [join(alone, "house.obj")]);
  await browser.WaitFor(
    `(${kSaid}).includes('warning') && ${kDrawn}`,
    `${chapter}: the .obj alone drawn`,
    20,
  );
  const warnings = await browser.Evaluate(kSaid);
  if (warnings !== warned.stderr.trimEnd())
    Fail(
      `${chapter}: for house.obj alone the page says "${warnings}", the program "${warned.stderr.trimEnd()}"`,
    );

  await browser.Evaluate(`(() => { const select = document.getElementById('model-choice'); select.value = '';
    select.dispatchEvent(new Event('change')); })()`);
  await browser.WaitFor(`${kDrawn} && ${kOwnFirst}`, `${chapter}: the chapter's figures again`);
  if (await browser.Evaluate(`!!document.getElementById('controls') && !(${kControlsShown})`))
    Fail(`${chapter}: back to none, the chapter's controls stay hidden`);
  await ShowFigure(browser, 0);
  if (
    !Same(
      await browser.CanvasDigest(),
      PngDigest(join(repo, "tests", "golden", chapter, `${own}.png`)),
    )
  ) {
    Fail(`${chapter}: back to none, ${own} differs from its golden image`);
  }
  console.log(
    `${chapter}: the picker's house as the program draws it, after a restart too; ` +
      `"${said}"; the .obj alone warned as the program warns; none: the chapter's ${own} again`,
  );
}

// An assimp model from a moved camera, as in the deep tier's corpus check.
async function CheckAssimp(browser, chapter, name) {
  const view = "2.2,0.5,1.2,51,-10";
  await browser.Open(`${chapter}/index.html?model=${name}&figure=model&view=${view}`);
  await browser.WaitFor(kDrawn, `${chapter}: ${name} drawn`, 120);
  const drawnNatively = Native(chapter, join(assimp, `${name}.obj`), [
    "--figure",
    "model",
    "--view",
    view,
  ]);
  if (!Same(await browser.CanvasDigest(), PngDigest(join(drawnNatively.out, "model.png")))) {
    Fail(`${chapter}: ${name} from ${view} differs from the native program's`);
  } else {
    console.log(`${chapter}: ${name} from ${view}, as the program draws it`);
  }
}

const browser = await Browser.Open(site);
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
  if (chapters.length < 8) Fail(`only ${chapters.length} chapters take --model: ${chapters}`);
  for (const chapter of chapters) await CheckSiteHouse(browser, chapter);
  await CheckPicker(browser, "14-textures");
  await CheckPicker(browser, "05-raytracer-extensions");
  if (existsSync(join(assimp, "spider.obj"))) {
    await CheckAssimp(browser, "14-textures", "spider");
    await CheckAssimp(browser, "05-raytracer-extensions", "WusonOBJ");
  } else {
    console.log(
      `no ${assimp}: the spider and the Wuson not checked (scripts/setup --deep installs them)`,
    );
  }
} finally {
  await browser.Close();
  rmSync(work, { recursive: true, force: true });
}
if (browser.outside.length)
  Fail(
    `the pages asked for what is not on this machine: ${[...new Set(browser.outside)].join(", ")}`,
  );
console.log(Failures() === 0 ? "PASS: the models of the site" : `${Failures()} failed`);
process.exit(Failures() === 0 ? 0 : 1);
