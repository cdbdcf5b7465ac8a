// A chapter's page (made by make_site.py): its figures drawn by the chapter's C++,
// compiled to WebAssembly (program/web/web_entry.cpp), in a worker (figures_client.js),
// so that the page answers while a figure takes seconds; a list of the figures and of
// the views of where the work goes; for a figure with a camera, the window's keys and
// mouse drag (program/camera_controls.h), and buttons for a screen without keys. The
// page opens at ?figure=NAME&view=x,y,z,yaw,pitch when asked, and keeps the figure shown
// in its address; what it cannot show is said in the page, and the chapter's opening
// figure drawn instead.
"use strict";

// The keys of program/camera_controls.h's CameraKey, in its order (0 to 9), named as
// KeyboardEvent.key names them: forward, back, right, left, up, down, turn left, turn
// right, look up, look down.
const kCameraKeys = [
  "ArrowUp",
  "ArrowDown",
  "d",
  "a",
  "PageUp",
  "PageDown",
  "q",
  "e",
  "Home",
  "End",
];

const live = document.getElementById("live");
const canvas = document.getElementById("canvas");
// Each figure's size: its golden image's (600 x 600, the programs' default, without one).
const sizes = JSON.parse(live.dataset.sizes);
const sizeOf = (name) => sizes[name] ?? [600, 600];

let figuresWorker = null;
let figures = []; // {name, caption, hasCamera, costPartner, hasCostView, button}
let shown = 0; // the index of the figure shown
let view = "0,0,0,0,0"; // the camera's view, kept here: a worker ended mid-draw forgets it
let settleTime = 150;
let settle = null; // the timer that draws the full frame once the camera stops
let wanted = null; // the frame to draw when the worker is free: 'full' or 'preview'
let drawing = false; // a Draw loop is running
let generation = 0; // counts the worker's restarts: a loop of an earlier one stops
let siteModel = ""; // the name of the site's model drawn (models.js), '' when none

function say(id, text) {
  const element = document.getElementById(id);
  element.textContent = text;
  element.hidden = text === "";
}

// Puts a frame on the canvas: a full one as it is, a preview stretched to the figure's
// size (as the window does).
function showFrame(frame, full, width, height) {
  const image = new ImageData(
    new Uint8ClampedArray(frame.pixels.buffer),
    frame.width,
    frame.height,
  );
  canvas.width = width;
  canvas.height = height;
  canvas.style.maxWidth = `${width}px`; // a 512-pixel figure at its own size, not stretched
  if (full) {
    canvas.getContext("2d").putImageData(image, 0, 0);
  } else {
    const preview = new OffscreenCanvas(image.width, image.height);
    preview.getContext("2d").putImageData(image, 0, 0);
    const context = canvas.getContext("2d");
    context.imageSmoothingEnabled = false;
    context.drawImage(preview, 0, 0, width, height);
  }
}

// Draws the figure shown, in the worker, at its full size or while the camera moves at
// the preview size; one frame at a time, the latest one wanted next.
async function draw(full) {
  wanted = full || wanted === "full" ? "full" : "preview";
  if (drawing) return;
  drawing = true;
  const mine = generation;
  while (wanted && mine === generation) {
    const isFull = wanted === "full";
    wanted = null;
    const index = shown;
    const figure = figures[index];
    const [width, height] = sizeOf(figure.name);
    const frame = await figuresWorker.request({
      op: "draw",
      index,
      width,
      height,
      full: isFull,
      view: figure.hasCamera ? view : undefined,
    });
    if (frame.cancelled || index !== shown || mine !== generation) continue;
    if (frame.problem) {
      say("problem", `${figure.name} could not be drawn: ${frame.problem}`);
      continue;
    }
    showFrame(frame, isFull, width, height);
    const time =
      frame.milliseconds < 10 ? frame.milliseconds.toFixed(1) : frame.milliseconds.toFixed(0);
    say(
      "status",
      `${figure.name}: ${frame.width} × ${frame.height} drawn in ${time} ms` +
        (isFull ? "" : ", at half size while the camera moves") +
        (frame.measured ? `; ${frame.measured}` : ""),
    );
    canvas.dataset.drawn = isFull ? "full" : "preview";
    canvas.dataset.milliseconds = frame.milliseconds;
  }
  if (mine === generation) drawing = false;
}

// The address: the figure shown, and its view where it has a camera.
function address() {
  const figure = figures[shown];
  const query = new URLSearchParams(siteModel ? { model: siteModel } : {});
  query.set("figure", figure.name);
  if (figure.hasCamera) query.set("view", view);
  return "?" + query.toString();
}

function showView() {
  const figure = figures[shown];
  document.getElementById("camera").hidden = !figure.hasCamera;
  document.getElementById("view").textContent = view;
  document.getElementById("view-link").href = address();
  history.replaceState(null, "", address());
}

// Gives up the frame being drawn, if any: the worker is ended and made anew.
function stopDrawing() {
  if (figuresWorker.busy) {
    figuresWorker.restart();
    ++generation;
    drawing = false;
  }
}

// Shows figure `index`: its button pressed, its caption, then its frame. A figure still
// being drawn is given up (the worker is ended and made anew: the business card takes
// seconds).
function selectFigure(index) {
  stopDrawing();
  shown = index;
  figures.forEach((figure, i) => figure.button.setAttribute("aria-checked", i === index));
  figures[index].button.scrollIntoView({ block: "nearest" });
  say("caption", figures[index].caption);
  say("status", `drawing ${figures[index].name}…`);
  document.dispatchEvent(new CustomEvent("cgfs-shown", { detail: figures[index].name }));
  const partner = figures[index].costPartner;
  document.getElementById("cost").hidden = partner < 0;
  if (partner >= 0) {
    document.getElementById("cost").textContent = figures[index].hasCostView
      ? `where the work goes: ${figures[partner].name} (C)`
      : `back to ${figures[partner].name} (C)`;
  }
  showView();
  delete canvas.dataset.drawn;
  requestAnimationFrame(() => setTimeout(() => draw(true)));
}

// After the camera moved: a half-size frame as soon as the worker is free, the full one
// once no key or drag has come for the settling time.
function cameraMoved() {
  showView();
  delete canvas.dataset.drawn;
  draw(false);
  clearTimeout(settle);
  settle = setTimeout(() => draw(true), settleTime);
}

// Moves the camera in the worker (program/camera_controls.h's arithmetic); the moves
// one after the other, each from the view the one before left.
let moves = Promise.resolve();
function moveCamera(move) {
  moves = moves.then(async () => {
    const answer = await figuresWorker.request({ op: "camera", view, ...move });
    if (answer.cancelled) return;
    if (answer.problem) {
      say("problem", answer.problem);
      return;
    }
    view = answer.view;
    cameraMoved();
  });
}

function onKey(event) {
  if (event.altKey || event.ctrlKey || event.metaKey) return;
  if (event.target.closest?.("#your-code, input, textarea, select, .CodeMirror")) return;
  const key = event.key.length === 1 ? event.key.toLowerCase() : event.key;
  if (key === "ArrowLeft" || key === "ArrowRight") {
    selectFigure((shown + (key === "ArrowLeft" ? figures.length - 1 : 1)) % figures.length);
  } else if (key === "c" && figures[shown].costPartner >= 0) {
    selectFigure(figures[shown].costPartner);
  } else if (figures[shown].hasCamera && kCameraKeys.includes(key)) {
    moveCamera({ key: kCameraKeys.indexOf(key) });
  } else if (figures[shown].hasCamera && key === "r") {
    moveCamera({ reset: true });
  } else {
    return;
  }
  event.preventDefault();
}

// Dragging the picture turns the camera, by the canvas's own pixels (the page may
// show the canvas smaller than it is).
function followDrags() {
  let last = null;
  canvas.addEventListener("pointerdown", (event) => {
    if (event.button !== 0 || !figures[shown].hasCamera) return;
    last = [event.clientX, event.clientY];
    canvas.setPointerCapture(event.pointerId);
    event.preventDefault();
  });
  canvas.addEventListener("pointermove", (event) => {
    if (last === null) return;
    const scale = canvas.width / canvas.getBoundingClientRect().width;
    const right = Math.round((event.clientX - last[0]) * scale);
    const down = Math.round((event.clientY - last[1]) * scale);
    if (right === 0 && down === 0) return;
    last = [last[0] + right / scale, last[1] + down / scale];
    moveCamera({ drag: [right, down] });
  });
  const stop = () => {
    last = null;
  };
  canvas.addEventListener("pointerup", stop);
  canvas.addEventListener("pointercancel", stop);
}

// The buttons that walk and turn the camera on a screen without keys: each a key of
// kCameraKeys, repeated while held.
function cameraButtons() {
  for (const button of document.querySelectorAll("#camera-pad button[data-key]")) {
    let repeat = null;
    const press = () => moveCamera({ key: Number(button.dataset.key) });
    button.addEventListener("pointerdown", (event) => {
      event.preventDefault();
      press();
      clearInterval(repeat);
      repeat = setInterval(press, 120);
    });
    for (const end of ["pointerup", "pointerleave", "pointercancel"]) {
      button.addEventListener(end, () => clearInterval(repeat));
    }
  }
  document
    .getElementById("camera-reset")
    .addEventListener("click", () => moveCamera({ reset: true }));
}

// The figure and view the address asks for, or the chapter's opening figure; what
// cannot be shown is said.
async function findOpening() {
  const query = new URLSearchParams(location.search);
  const problems = [];
  const opening = figures.findIndex((figure) => figure.name === live.dataset.opening);
  let index = Math.max(0, opening);
  if (query.has("figure")) {
    const asked = figures.findIndex((figure) => figure.name === query.get("figure"));
    if (asked < 0) {
      problems.push(
        `This chapter has no figure "${query.get("figure")}"; its figures are listed above.`,
      );
    } else {
      index = asked;
    }
  }
  if (query.has("view")) {
    if (!figures[index].hasCamera) {
      problems.push(
        `${figures[index].name} has no camera to move; the view "${query.get("view")}" is not used.`,
      );
    } else {
      const answer = await figuresWorker.request({ op: "camera", set: query.get("view") });
      if (answer.problem)
        problems.push(
          `No view "${query.get("view")}": ${answer.problem}; the chapter's own view is shown.`,
        );
      else view = answer.view;
    }
  }
  say("problem", problems.join(" "));
  return index;
}

// The figures, in two lists: the figures, and the views of where the work goes (those
// another figure's C switches to). Lists there were are replaced, and the view is the
// chapter's again (a model's figures replace the chapter's, models.js).
function listFigures(described) {
  document.getElementById("figures").replaceChildren();
  document.getElementById("cost-views").replaceChildren();
  figures = [];
  view = "0,0,0,0,0";
  const isCostView = (figure) => figure.costPartner >= 0 && !figure.hasCostView;
  for (const [i, each] of described.entries()) {
    const figure = { ...each };
    figure.button = document.createElement("button");
    figure.button.type = "button";
    figure.button.textContent = figure.name;
    figure.button.setAttribute("role", "radio");
    figure.button.addEventListener("click", () => selectFigure(i));
    document.getElementById(isCostView(figure) ? "cost-views" : "figures").append(figure.button);
    figures.push(figure);
  }
  document.getElementById("cost-views-group").hidden = !figures.some(isCostView);
  // The chapter's controls choose among its own figures: hidden while a model's replace them.
  const controls = document.getElementById("controls");
  if (controls) {
    const listed = new Set(figures.map((figure) => figure.name));
    controls.hidden = !JSON.parse(controls.dataset.controls).some(({ values }) =>
      values.some(([, name]) => listed.has(name)),
    );
  }
  // How many there are: the list shows three rows, and scrolls.
  const costViews = figures.filter(isCostView).length;
  const plural = (n, one, many) => `${n} ${n === 1 ? one : many}`;
  say(
    "figures-count",
    plural(figures.length - costViews, "figure", "figures") +
      (costViews ? ` and ${plural(costViews, "view", "views")} of where the work goes` : "") +
      (figures.length > 9 ? ": the list scrolls" : ""),
  );
}

// The other column's two tabs: the chapter's README, and the reader's own code. On a
// wide screen the code's tab shows the README beside the editor, in place of the
// figures (site.css: main[data-tab="tab-code"]); on a narrow one, the editor alone.
function setUpTabs() {
  const tabs = [
    ["tab-readme", "readme"],
    ["tab-code", "your-code"],
  ];
  const wide = matchMedia("(min-width: 1100px)");
  let chosen = "tab-readme";
  const show = (tab) => {
    chosen = tab;
    for (const [each, panel] of tabs) {
      document.getElementById(each).setAttribute("aria-selected", each === tab);
      const element = document.getElementById(panel);
      if (element) element.hidden = each !== tab && !(panel === "readme" && wide.matches);
    }
    document.querySelector("main.chapter").dataset.tab = tab;
    document.dispatchEvent(new CustomEvent("cgfs-tab", { detail: tab }));
  };
  for (const [tab] of tabs) document.getElementById(tab).addEventListener("click", () => show(tab));
  wide.addEventListener("change", () => show(chosen));
  if (!document.getElementById("your-code")) document.getElementById("tabs").hidden = true;
  show(
    location.hash === "#your-code" || location.hash.startsWith("#code=")
      ? "tab-code"
      : "tab-readme",
  );
}

// The chapter's parameters as controls (make_site.py's controls_box, controls.json): for
// each scene a parameter, each of its values one of the chapter's figures. Choosing a
// value shows that figure; showing a figure sets the control it belongs to. A value
// chosen here is told to the Your code panel (the event cgfs-figure), which draws the
// reader's own beside it when asked.
function setUpControls() {
  const box = document.getElementById("controls");
  if (!box) return;
  const groups = JSON.parse(box.dataset.controls);
  const rows = [];
  for (const [g, { scene, parameter, values }] of groups.entries()) {
    const row = document.createElement("fieldset");
    row.className = "control";
    const legend = document.createElement("legend");
    legend.textContent = `${scene}: ${parameter}`;
    row.append(legend);
    for (const [label, figure] of values) {
      const choice = document.createElement("label");
      const radio = Object.assign(document.createElement("input"), {
        type: "radio",
        name: `control-${g}`,
        value: figure,
      });
      radio.addEventListener("change", () => {
        const index = figures.findIndex((each) => each.name === figure);
        if (index < 0) return;
        selectFigure(index);
        document.dispatchEvent(new CustomEvent("cgfs-figure", { detail: figure }));
      });
      choice.append(radio, ` ${label}`);
      row.append(choice);
    }
    rows.push(row);
  }
  box.querySelector(".controls-title").after(...rows);
  document.addEventListener("cgfs-shown", ({ detail }) => {
    for (const radio of box.querySelectorAll('input[type="radio"]'))
      radio.checked = radio.value === detail;
  });
}

async function start() {
  setUpTabs();
  setUpControls();
  figuresWorker = new FiguresWorker(
    live.dataset.module,
    CGFS_FIGURES_OF[live.dataset.chapter],
    (fraction) => {
      say("status", `drawing ${figures[shown].name}… ${Math.round(fraction * 100)} %`);
    },
  );
  let described = await figuresWorker.request({ op: "describe" });
  if (described.problem) throw new Error(described.problem);
  settleTime = described.settle;
  if (document.getElementById("model")) described = (await modelsStart()) ?? described;
  listFigures(described.figures);
  document
    .getElementById("cost")
    .addEventListener("click", () => selectFigure(figures[shown].costPartner));
  document.getElementById("reset").addEventListener("click", () => moveCamera({ reset: true }));
  document.addEventListener("keydown", onKey);
  followDrags();
  cameraButtons();
  selectFigure(await findOpening());
  live.dataset.ready = "yes";
}

start().catch((error) => {
  say("status", "");
  say("problem", `The chapter's code could not be loaded: ${error.message ?? error}`);
});
