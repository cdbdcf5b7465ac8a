// Which cases a chapter's check runs: the chapter's own (tests/cases/NN-name.json), and
// those of the earlier chapters whose functions it keeps unchanged ("keeps" in its case
// file), each with the signature the student's function has.

// Seconds a student's file may take to load (apart from its cases), and one case by default.
export const LOAD_LIMIT = 60;
export const CASE_LIMIT = 5;

// A chapter's name from what a student typed: "02", "02-basic-rays" (null if none).
export function chapterNamed(typed, chapters) {
  if (!/^[0-9]{2}(-[a-z0-9-]+)?$/.test(typed)) return null;
  const found = chapters.filter((name) => name.startsWith(typed));
  return found.length === 1 ? found[0] : null;
}

// The sections of a chapter's check: its own functions first, then each earlier
// chapter's that it keeps, with the earlier functions it changes and why.
//   files: chapter name -> its parsed case file.
export function sections(chapter, files) {
  const own = files[chapter];
  const list = [{ chapter, own: true, entries: own.functions, changed: [] }];
  for (const [earlier, names] of Object.entries(own.keeps ?? {})) {
    const entries = files[earlier].functions.filter((entry) => names.includes(entry.function));
    const changed = Object.entries(own.changes?.[earlier] ?? {}).map(([name, why]) => ({
      function: name,
      why,
    }));
    list.push({ chapter: earlier, own: false, entries, changed });
  }
  return list;
}

// Every book function a chapter's check may call.
export function functionsOf(list) {
  const names = new Set();
  for (const section of list) {
    for (const entry of section.entries) names.add(entry.function);
    for (const { function: name } of section.changed) names.add(name);
  }
  return [...names];
}

// The signature the checker calls a student's function with: the book's (the entry's
// parameters), or one the entry lists beside it (Listing 3-1's ComputeLighting(P, N), the
// demos' ViewportToCanvas(p2d)), picked by how many parameters the student's function
// takes; null when none fits. `parameters`: what the runner found, or null (unknown: the
// book's).
export function signatureFor(entry, parameters) {
  const book = { call: entry.call, where: entry.where, parameters: entry.parameters };
  if (!parameters) return book;
  const fits = (count) =>
    parameters.required <= count && (count <= parameters.names.length || parameters.more);
  return [book, ...(entry.signatures ?? [])].find((each) => fits(each.parameters.length)) ?? null;
}

// The cases a signature runs: all the book's; an alternative's those it lists (Listing
// 3-1's ComputeLighting: the cases where s = -1, matte, makes V and s idle).
export function casesFor(entry, signature) {
  return entry.cases
    .map((kase, index) => ({ kase, number: index + 1 }))
    .filter(({ number }) => !signature.cases || signature.cases.includes(number));
}
