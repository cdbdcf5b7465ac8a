// The contracts between chapters in tests/cases: every function a chapter's file keeps
// from an earlier one has cases there and is declared by the keeping chapter's own
// headers (chapters/NN-name/*.h), every changed function exists, and every alternative
// signature lists cases that exist and takes fewer parameters than the book's, or as many
// of other kinds. Prints what is wrong, one line each; exit status 1 if anything is.
// Usage: node check_case_files.mjs SOURCE_DIR

import fs from "node:fs";
import path from "node:path";

const root = process.argv[2];
const casesDir = path.join(root, "tests", "cases");
const files = Object.fromEntries(
  fs
    .readdirSync(casesDir)
    .filter((f) => f.endsWith(".json"))
    .sort()
    .map((f) => [
      f.replace(/\.json$/, ""),
      JSON.parse(fs.readFileSync(path.join(casesDir, f), "utf8")),
    ]),
);
const headers = (chapter) =>
  fs
    .readdirSync(path.join(root, "chapters", chapter))
    .filter((f) => f.endsWith(".h"))
    .map((f) => fs.readFileSync(path.join(root, "chapters", chapter, f), "utf8"))
    .join("\n");

const problems = [];
for (const [chapter, file] of Object.entries(files)) {
  const declared = headers(chapter);
  for (const [earlier, names] of Object.entries(file.keeps ?? {})) {
    if (!files[earlier] || earlier >= chapter)
      problems.push(`${chapter}: keeps from ${earlier}, not an earlier chapter with cases`);
    for (const name of names) {
      if (!files[earlier]?.functions.some((entry) => entry.function === name))
        problems.push(`${chapter}: keeps ${earlier}'s ${name}, which has no cases there`);
      if (!new RegExp(`\\b${name}\\(`).test(declared))
        problems.push(`${chapter}: keeps ${earlier}'s ${name}, which its headers do not declare`);
    }
  }
  for (const [earlier, changed] of Object.entries(file.changes ?? {})) {
    for (const name of Object.keys(changed)) {
      if (!files[earlier]?.functions.some((entry) => entry.function === name))
        problems.push(`${chapter}: changes ${earlier}'s ${name}, which has no cases there`);
      if (file.keeps?.[earlier]?.includes(name))
        problems.push(`${chapter}: both keeps and changes ${earlier}'s ${name}`);
    }
  }
  for (const entry of file.functions) {
    for (const signature of entry.signatures ?? []) {
      for (const number of signature.cases ?? []) {
        if (!(number >= 1 && number <= entry.cases.length))
          problems.push(
            `${chapter}: ${entry.function}'s ${signature.call} lists case ${number}, which does not exist`,
          );
      }
      if (signature.parameters.length === entry.parameters.length) {
        problems.push(
          `${chapter}: ${entry.function}'s ${signature.call} takes as many parameters as the book's: the checker could not tell them apart`,
        );
      }
    }
  }
}
for (const line of problems) console.log(line);
process.exit(problems.length ? 1 : 0);
