// The chapter page's Python against this machine's CPython, side by side in one run
// (docs/students.md, "3. On the chapter's page"): Python's cold start on the page (from
// choosing it to an interpreter ready), and a figure drawn with our reference chapter,
// on the page (Pyodide in a Web Worker, timed by the page) and by CPython through the same
// runner (cpython_draw.py), interleaved, each ROUNDS times. Prints the medians and their
// ratio; a measurement, with no verdict (the machine's load is in every number).
//
// Usage: node python_speed.mjs REPO SITE [ROUNDS] [CHAPTER FIGURE]
import { spawnSync } from "node:child_process";
import { readFileSync, readdirSync } from "node:fs";
import { join, resolve } from "node:path";
import { Browser, sleep } from "./browser.mjs";
import { NAMES } from "../../tools/check-functions/core/names.mjs";

const [repo, site] = process.argv.slice(2, 4).map((p) => resolve(p));
const rounds = Number(process.argv[4] ?? 3);
const [chapter, figure] = [process.argv[5] ?? "02-basic-rays", process.argv[6] ?? "fig-2-11"];
const folder = join(repo, "tools", "check-functions", "reference", "python");
const file = join(
  folder,
  readdirSync(folder).find((name) =>
    readFileSync(join(folder, name), "utf8").startsWith(`# cases: ${chapter.slice(0, 2)} `),
  ),
);
const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const panel = (what) => `document.getElementById('code-panel').${what}`;

const browser = await Browser.open(site);
const starts = [];
const page = [];
const cpython = [];
try {
  for (let round = 0; round < rounds; ++round) {
    await browser.open(`${chapter}/index.html`);
    await browser.waitFor(`${panel("dataset.ready")} === 'yes'`, "the panel");
    await browser.evaluate(`(() => { document.getElementById('tab-code').click(); const s = document.getElementById('code-language');
      s.value = 'python'; s.dispatchEvent(new Event('change')); window.__chosen = performance.now(); })()`);
    await browser.waitFor('supplyFor("python").readyNow >= 1', "Python started", 120);
    starts.push(await browser.evaluate("(performance.now() - window.__chosen) / 1000"));
    await browser.waitFor('supplyFor("python").readyNow >= 2', "a second Python started", 120);
    await browser.evaluate(
      `document.querySelector('#code-panel .CodeMirror').CodeMirror.setValue(${JSON.stringify(readFileSync(file, "utf8"))})`,
    );
    await browser.evaluate(`(() => { document.getElementById('code-figure').value = '${figure}';
      document.getElementById('code-draw').click(); })()`);
    await sleep(100);
    await browser.waitFor(`${panel("dataset.busy")} === ''`, "the draw", 600);
    const status = await browser.evaluate("document.getElementById('code-status').textContent");
    const seconds = /drawn with your functions in ([\d.]+) s/.exec(status)?.[1];
    if (!seconds) throw new Error(`the page's draw: ${status}`);
    page.push(Number(seconds));
    const run = spawnSync(
      "python3",
      [join(repo, "tests", "site", "cpython_draw.py"), repo, chapter, figure, file],
      { input: JSON.stringify(NAMES), encoding: "utf8" },
    );
    if (run.status !== 0) throw new Error(`cpython_draw.py: ${run.stderr}`);
    cpython.push(Number(run.stdout));
    console.log(
      `round ${round + 1}: Python started on the page in ${starts.at(-1).toFixed(1)} s; ${figure} drawn ` +
        `on the page in ${page.at(-1).toFixed(1)} s, by CPython in ${cpython.at(-1).toFixed(1)} s`,
    );
  }
} finally {
  await browser.close();
}
const version = spawnSync("python3", ["--version"], { encoding: "utf8" }).stdout.trim();
console.log(
  `medians of ${rounds}: Python's cold start on the page ${median(starts).toFixed(1)} s; ${chapter}/${figure} ` +
    `drawn on the page in ${median(page).toFixed(1)} s, by ${version} in ${median(cpython).toFixed(1)} s: ` +
    `${(median(page) / median(cpython)).toFixed(1)} times as long`,
);
