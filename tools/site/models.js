// A model of the reader's own on the page of a chapter whose program takes --model
// (make_site.py adds the picker): one of the site's models (models/NAME.js, a model's
// files as text, since a page opened from a file may load a script but not fetch a file)
// or the reader's, chosen with the browser's file picker, the .obj with its .mtl and
// textures. Their files are given to the chapter's code with the words `--model
// NAME.obj` (figures_worker.js's options): read by the same reader as the program's,
// compiled with it, and drawn by the chapter's own code; what the program would print
// (its warnings, or the one line that says why not) is shown under the picker.
"use strict";

// The largest file the programs read (program/src/model_file.cpp): a larger one is not
// even read into the page.
const kMaxModelFileBytes = 128 * 1024 * 1024;

const modelScripts = {}; // a site model's name -> the promise of its files

// The site's model `name`: { open: its .obj's name, files: [{ name, bytes }] }.
function loadSiteModel(name) {
  modelScripts[name] ??= new Promise((resolve, reject) => {
    const script = document.createElement("script");
    script.src = `../models/${encodeURIComponent(name)}.js`;
    script.onload = () => {
      const model = self.CGFS_MODELS?.[name];
      if (!model) {
        reject(new Error(`the site has no model "${name}"`));
        return;
      }
      const files = Object.entries(model.files).map(([file, base64]) => ({
        name: file,
        bytes: Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)),
      }));
      resolve({ open: model.open, files });
    };
    script.onerror = () => reject(new Error(`the site has no model "${name}"`));
    document.head.append(script);
  });
  return modelScripts[name];
}

// The reader's files, chosen with the picker: { open, files }, or a line saying why they
// cannot be drawn.
async function ownModel(chosen) {
  const objs = chosen.filter((file) => /\.obj$/i.test(file.name));
  if (objs.length !== 1) {
    return (
      `Choose one .obj file, with its .mtl and texture files if it has them: ${objs.length} of the ` +
      `${chosen.length} files chosen are .obj files.`
    );
  }
  const large = chosen.find((file) => file.size > kMaxModelFileBytes);
  if (large)
    return `${large.name} is ${Math.round(large.size / 2 ** 20)} MB, more than the 128 MB the programs read.`;
  const files = await Promise.all(
    chosen.map(async (file) => ({
      name: file.name,
      bytes: new Uint8Array(await file.arrayBuffer()),
    })),
  );
  return { open: objs[0].name, files };
}

function sayModel(lines) {
  const said = document.getElementById("model-said");
  said.textContent = lines.join("\n");
  said.hidden = lines.length === 0;
}

// The list's entry for the reader's own model while it is drawn ("your own: NAME", the
// value '#own'), so that the list names what is drawn; none when `name` is null.
function showOwnChoice(name) {
  const select = document.getElementById("model-choice");
  let option = select.querySelector('option[value="#own"]');
  if (name === null) {
    option?.remove();
    return;
  }
  if (!option) {
    option = new Option("", "#own");
    select.append(option);
  }
  option.textContent = `your own: ${name}`;
}

// The chapter's figures made with `model` (none: its own): the figures as the worker
// describes them, or null when the program refused the model (its line is shown, and
// the figures stay as they were).
async function useModel(model) {
  stopDrawing();
  sayModel(model ? [`reading ${model.open}…`] : []);
  const answer = await figuresWorker.configure({
    op: "options",
    files: model?.files ?? [],
    words: model ? ["--model", model.open] : [],
  });
  sayModel(answer.problem ? [answer.problem] : (answer.lines ?? []));
  if (answer.problem || answer.status !== 0) {
    // The line that says why is brought into view: it is below the picture.
    document.getElementById("model-said").scrollIntoView({ block: "nearest" });
    return null;
  }
  return answer;
}

// After a choice (`name`: a site model's, '' for none, '#own' for the reader's files):
// the new figures listed and the first shown; a refused model leaves the figures, and
// the list, as they were.
async function modelChosen(model, name) {
  const select = document.getElementById("model-choice");
  const was = select.querySelector('option[value="#own"]') ? "#own" : siteModel;
  const described = await useModel(model);
  if (!described) {
    select.value = was;
    return;
  }
  showOwnChoice(name === "#own" ? model.open : null);
  siteModel = name === "#own" ? "" : name;
  select.value = name;
  listFigures(described.figures);
  selectFigure(0);
}

// The picker's controls; and the site's model the address names (?model=NAME), drawn
// before the page's first figure: its figures, or null for the chapter's own.
async function modelsStart() {
  const select = document.getElementById("model-choice");
  const input = document.getElementById("model-files");
  select.addEventListener("change", async () => {
    try {
      await modelChosen(select.value ? await loadSiteModel(select.value) : null, select.value);
    } catch (error) {
      sayModel([error.message]);
      select.value = select.querySelector('option[value="#own"]') ? "#own" : siteModel;
    }
  });
  input.addEventListener("change", async () => {
    const chosen = Array.from(input.files);
    input.value = "";
    if (chosen.length === 0) return;
    const model = await ownModel(chosen);
    if (typeof model === "string") sayModel([model]);
    else await modelChosen(model, "#own");
  });
  const asked = new URLSearchParams(location.search).get("model");
  if (!asked) return null;
  try {
    const described = await useModel(await loadSiteModel(asked));
    if (described) {
      siteModel = asked;
      select.value = asked;
    }
    return described;
  } catch (error) {
    sayModel([`${error.message}; the chapter's own figures are shown.`]);
    return null;
  }
}
