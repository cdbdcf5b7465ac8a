#!/usr/bin/env node
// The function checker against the corpus of student chapters in tests/check-functions/
// corpus (corpus.json): written apart from the references, in natural styles. Each file
// passes as written, with no adapter and no edit but the one its entry names (or, where
// it truly differs from the book, fails with the one line its entry gives, for each
// function its entry's `differs` lists); with
// --mistakes, also each planted mistake fails the function it is in, and the first line
// of that function's block after its heading is the one its entry gives (the test
// command runs the files as written; scripts/deep-checks' mistakes part, the mistakes
// too: a hundred checks cost more of the test command's four minutes than it has). A
// file whose entry needs numpy runs with a python3 that has it (the one on PATH, else
// /usr/bin/python3), and is skipped, said, where none has.
// Usage: check_corpus.mjs SOURCE_DIR WORK_DIR [--mistakes]
import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";

const [source, work, option] = process.argv.slice(2);
const withMistakes = option === "--mistakes";
const corpus = path.join(source, "tests", "check-functions", "corpus");
const checker = path.join(source, "tools", "check-functions", "check-functions.js");
const { files } = JSON.parse(fs.readFileSync(path.join(corpus, "corpus.json"), "utf8"));
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });

let failed = 0,
  checks = 0;
const check = (what, ok, output = "") => {
  checks++;
  console.log(`${ok ? "ok" : "FAIL"}: ${what}`);
  if (!ok) {
    failed++;
    console.log(
      output
        .split("\n")
        .map((line) => `    ${line}`)
        .join("\n"),
    );
  }
};

// A python3 with `module`, as a PATH that finds it first; null where there is none.
function pathWith(module) {
  if (!module) return process.env.PATH;
  for (const python of ["python3", "/usr/bin/python3"]) {
    if (spawnSync(python, ["-c", `import ${module}`], { stdio: "ignore" }).status === 0) {
      return python === "python3" ? process.env.PATH : `/usr/bin:${process.env.PATH}`;
    }
  }
  return null;
}

function run(chapter, file, adapter, envPath) {
  const args = [checker, chapter, file, ...(adapter ? ["--adapter", adapter] : [])];
  const result = spawnSync("node", args, {
    encoding: "utf8",
    env: { ...process.env, PATH: envPath },
  });
  return { status: result.status, output: `${result.stdout}${result.stderr}` };
}

// The lines of a function's block: its heading, then what follows until the next heading.
function block(output, name) {
  const lines = output.split("\n");
  const start = lines.findIndex((line) => new RegExp(`^  ${name} +`).test(line));
  if (start < 0) return [];
  const end = lines.findIndex((line, i) => i > start && /^\S|^  \S/.test(line));
  return lines.slice(start, end < 0 ? undefined : end);
}

const styles = new Map();
for (const entry of files) {
  const envPath = pathWith(entry.needs);
  if (envPath === null) {
    console.log(`skipped: ${entry.file} (no python3 here has ${entry.needs})`);
    continue;
  }
  const chapter = entry.chapter;
  const folder = path.join(work, entry.file.replace(/\W/g, "_"));
  fs.mkdirSync(folder);
  const file = path.join(folder, entry.file);
  const original = fs.readFileSync(path.join(corpus, entry.file), "utf8");
  fs.writeFileSync(file, original);
  const adapter = entry.adapter && path.join(folder, entry.adapter);
  if (adapter) fs.copyFileSync(path.join(corpus, entry.adapter), adapter);
  const language = /\.py$/.test(entry.file) ? "Python" : "JavaScript";
  styles.set(language, (styles.get(language) ?? 0) + 1);

  const as = run(chapter, file, adapter, envPath);
  if (entry.differs) {
    const differs = [entry.differs].flat();
    for (const { function: name, first } of differs) {
      const lines = block(as.output, name);
      check(
        `${entry.file}: where it differs from the book, ${name} fails with one line saying why`,
        as.status === 1 && /FAILED/.test(lines[0] ?? "") && new RegExp(first).test(lines[1] ?? ""),
        as.output,
      );
    }
    check(
      `${entry.file}: and every other function passes`,
      as.output
        .split("\n")
        .filter(
          (line) => /^  \S/.test(line) && !differs.some((each) => line.includes(each.function)),
        )
        .every((line) => / passed \(| not checked against /.test(line)),
      as.output,
    );
  } else {
    check(
      `${entry.file} (${entry.style}): complete as written`,
      as.status === 0 && /^chapter: complete /m.test(as.output),
      as.output,
    );
  }
  for (const mistake of withMistakes ? (entry.mistakes ?? []) : []) {
    if (!original.includes(mistake.find)) {
      check(
        `${entry.file}: the mistake's text is in the file: ${JSON.stringify(mistake.find)}`,
        false,
      );
      continue;
    }
    fs.writeFileSync(file, original.replace(mistake.find, mistake.replace));
    const got = run(chapter, file, adapter, envPath);
    const lines = block(got.output, mistake.function);
    check(
      `${entry.file}: ${JSON.stringify(mistake.replace.trim() || `no ${mistake.find.trim()}`)} fails ${mistake.function}, ` +
        `first: ${mistake.first}`,
      got.status === 1 &&
        /FAILED/.test(lines[0] ?? "") &&
        new RegExp(mistake.first).test(lines[1] ?? ""),
      got.output,
    );
  }
  fs.writeFileSync(file, original);
}
console.log(
  `corpus: ${[...styles].map(([language, count]) => `${count} ${language}`).join(", ")} files, ${checks} checks`,
);
// docs/students.md counts the corpus: its files in each language, its planted mistakes.
const docs = fs.readFileSync(path.join(source, "docs", "students.md"), "utf8").replace(/\s+/g, " ");
const said = /(\d+) files, (\d+) in JavaScript and (\d+) in Python/.exec(docs);
const mistakes = files.reduce((sum, entry) => sum + (entry.mistakes ?? []).length, 0);
const [javascript, python] = ["JavaScript", "Python"].map(
  (language) =>
    files.filter((entry) => /\.py$/.test(entry.file) === (language === "Python")).length,
);
check(
  `docs/students.md counts the corpus: ${files.length} files, ${javascript} in JavaScript and ${python} in Python; ${mistakes} mistakes`,
  said?.slice(1).join() === [files.length, javascript, python].join() &&
    new RegExp(`one at a time \\(${mistakes} in all\\)`).test(docs),
);
if (failed === 0) {
  console.log(
    `PASS: the corpus passes as written${withMistakes ? ", and every planted mistake is caught where it is" : ""}`,
  );
}
process.exit(failed ? 1 : 0);
