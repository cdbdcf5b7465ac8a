// A chapter's page (made by make_site.py): its figures drawn by the chapter's C++,
// compiled to WebAssembly (figures.js, program/web/web_entry.cpp), one button per
// figure, and for a figure with a camera the window's keys and mouse drag
// (program/camera_controls.h). The page opens at ?figure=NAME&view=x,y,z,yaw,pitch
// when asked; one it cannot show is said in the page, and the chapter's first figure
// drawn instead.
'use strict';

// The keys of program/camera_controls.h's CameraKey, in its order (0 to 9), named as
// KeyboardEvent.key names them: forward, back, right, left, up, down, turn left, turn
// right, look up, look down.
const kCameraKeys = ['ArrowUp', 'ArrowDown', 'd', 'a', 'PageUp', 'PageDown', 'q', 'e', 'Home', 'End'];

const live = document.getElementById('live');
const canvas = document.getElementById('canvas');
// Each figure's size: its golden image's (600 x 600, the programs' default, without one).
const sizes = JSON.parse(live.dataset.sizes);
const SizeOf = (name) => sizes[name] ?? [600, 600];

let chapter = null;   // the chapter's WebAssembly module
let figures = [];     // {name, caption, hasCamera, button}
let shown = 0;        // the index of the figure shown
let settle = null;    // the timer that draws the full frame once the camera stops
let pending = false;  // a half-size frame is asked for and not drawn yet

function Say(id, text) {
  const element = document.getElementById(id);
  element.textContent = text;
  element.hidden = text === '';
}

function Text(pointer) { return chapter.UTF8ToString(pointer); }

// Draws the figure shown, at its full size or, while the camera moves, at the preview
// size stretched over the canvas (as the window does), and says how long it took.
function Draw(full) {
  const figure = figures[shown];
  const [width, height] = SizeOf(figure.name);
  const side = (n) => (full ? n : chapter._PreviewSide(n));
  const start = performance.now();
  if (!chapter._DrawFigure(shown, side(width), side(height))) {
    Say('problem', `${figure.name} could not be drawn: ${Text(chapter._LastError())}`);
    return;
  }
  const milliseconds = performance.now() - start;
  const bytes = side(width) * side(height) * 4;
  const pixels = new Uint8ClampedArray(chapter.HEAPU8.buffer, chapter._Pixels(), bytes);
  const image = new ImageData(new Uint8ClampedArray(pixels), side(width), side(height));
  canvas.width = width;
  canvas.height = height;
  if (full) {
    canvas.getContext('2d').putImageData(image, 0, 0);
  } else {
    const preview = new OffscreenCanvas(image.width, image.height);
    preview.getContext('2d').putImageData(image, 0, 0);
    const context = canvas.getContext('2d');
    context.imageSmoothingEnabled = false;
    context.drawImage(preview, 0, 0, width, height);
  }
  const time = milliseconds < 10 ? milliseconds.toFixed(1) : milliseconds.toFixed(0);
  Say('status', `${figure.name}: ${side(width)} × ${side(height)} drawn in ${time} ms` +
                (full ? '' : ', at half size while the camera moves'));
  canvas.dataset.drawn = full ? 'full' : 'preview';
  canvas.dataset.milliseconds = milliseconds;
}

// The view shown, and a link that opens the page at it and at this figure.
function ShowView() {
  const figure = figures[shown];
  const query = new URLSearchParams({figure: figure.name});
  document.getElementById('camera').hidden = !figure.hasCamera;
  if (figure.hasCamera) {
    const view = Text(chapter._ViewText());
    document.getElementById('view').textContent = view;
    query.set('view', view);
  }
  document.getElementById('view-link').href = '?' + query.toString();
}

// Shows figure `index`: its button pressed, its caption, then its frame, drawn once
// the page has shown that it is drawing (some figures take seconds).
function Select(index) {
  shown = index;
  figures.forEach((figure, i) => figure.button.setAttribute('aria-checked', i === index));
  Say('caption', figures[index].caption);
  Say('status', `drawing ${figures[index].name}…`);
  const partner = figures[index].costPartner;
  document.getElementById('cost').hidden = partner < 0;
  if (partner >= 0) {
    document.getElementById('cost').textContent = figures[index].hasCostView
      ? `where the work goes: ${figures[partner].name} (C)` : `back to ${figures[partner].name} (C)`;
  }
  ShowView();
  requestAnimationFrame(() => setTimeout(() => Draw(true)));
}

// After the camera moved: a half-size frame at the next animation frame, the full one
// once no key or drag has come for the settling time.
function CameraMoved() {
  ShowView();
  if (!pending) {
    pending = true;
    requestAnimationFrame(() => { pending = false; Draw(false); });
  }
  clearTimeout(settle);
  settle = setTimeout(() => Draw(true), chapter._SettleMilliseconds());
}

function OnKey(event) {
  if (event.altKey || event.ctrlKey || event.metaKey) return;
  const key = event.key.length === 1 ? event.key.toLowerCase() : event.key;
  if (key === 'ArrowLeft' || key === 'ArrowRight') {
    Select((shown + (key === 'ArrowLeft' ? figures.length - 1 : 1)) % figures.length);
  } else if (key === 'c' && figures[shown].costPartner >= 0) {
    Select(figures[shown].costPartner);
  } else if (figures[shown].hasCamera && kCameraKeys.includes(key)) {
    chapter._PressCameraKey(kCameraKeys.indexOf(key));
    CameraMoved();
  } else if (figures[shown].hasCamera && key === 'r') {
    chapter._ResetView();
    CameraMoved();
  } else {
    return;
  }
  event.preventDefault();
}

// Dragging the picture turns the camera, by the canvas's own pixels (the page may
// show the canvas smaller than it is).
function FollowDrags() {
  let last = null;
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 || !figures[shown].hasCamera) return;
    last = [event.clientX, event.clientY];
    canvas.setPointerCapture(event.pointerId);
    event.preventDefault();
  });
  canvas.addEventListener('pointermove', (event) => {
    if (last === null) return;
    const scale = canvas.width / canvas.getBoundingClientRect().width;
    const right = Math.round((event.clientX - last[0]) * scale);
    const down = Math.round((event.clientY - last[1]) * scale);
    if (right === 0 && down === 0) return;
    last = [last[0] + right / scale, last[1] + down / scale];
    chapter._DragCamera(right, down);
    CameraMoved();
  });
  const stop = () => { last = null; };
  canvas.addEventListener('pointerup', stop);
  canvas.addEventListener('pointercancel', stop);
}

// The figure and view the address asks for; what cannot be shown is said.
function Opening() {
  const query = new URLSearchParams(location.search);
  const problems = [];
  let index = 0;
  if (query.has('figure')) {
    index = figures.findIndex((figure) => figure.name === query.get('figure'));
    if (index < 0) {
      problems.push(`This chapter has no figure "${query.get('figure')}"; its figures are the buttons above.`);
      index = 0;
    }
  }
  if (query.has('view')) {
    if (!figures[index].hasCamera) {
      problems.push(`${figures[index].name} has no camera to move; the view "${query.get('view')}" is not used.`);
    } else {
      const text = chapter.allocateUTF8(query.get('view'));
      if (!chapter._SetView(text)) {
        problems.push(`No view "${query.get('view')}": ${Text(chapter._LastError())}; the chapter's own view is shown.`);
      }
      chapter._free(text);
    }
  }
  Say('problem', problems.join(' '));
  return index;
}

function Start(module) {
  chapter = module;
  const list = document.getElementById('figures');
  for (let i = 0; i < chapter._FigureCount(); ++i) {
    const figure = {name: Text(chapter._FigureName(i)), caption: Text(chapter._FigureCaption(i)),
                    hasCamera: chapter._FigureHasCamera(i) === 1,
                    costPartner: chapter._FigureCostPartner(i),
                    hasCostView: chapter._FigureHasCostView(i) === 1};
    figure.button = document.createElement('button');
    figure.button.type = 'button';
    figure.button.textContent = figure.name;
    figure.button.setAttribute('role', 'radio');
    figure.button.addEventListener('click', () => Select(i));
    list.append(figure.button);
    figures.push(figure);
  }
  document.getElementById('cost').addEventListener('click', () => Select(figures[shown].costPartner));
  document.getElementById('reset').addEventListener('click', () => { chapter._ResetView(); CameraMoved(); });
  document.addEventListener('keydown', OnKey);
  FollowDrags();
  Select(Opening());
  live.dataset.ready = 'yes';
}

window[live.dataset.module]().then(Start, (error) => {
  Say('status', '');
  Say('problem', `The chapter's code could not be loaded: ${error}`);
});
