// A chapter's figures, drawn off the page's thread (chapter.js, index.js, yourcode.js):
// this worker holds the chapter's C++ compiled to WebAssembly (its figures.js, whose text
// comes first in the worker, with CGFS_MODULE naming its factory) and answers the page,
// one request at a time, each { id, op, ... } answered { id, ... }:
//   describe                 the chapter's figures: name, caption, camera, cost view
//   draw index width height full view
//                            the figure at that size (half of it, stretched by the page,
//                            while the camera moves: full false), from that view; its
//                            pixels (RGBA) and what it measured (a cost view's totals),
//                            or a problem; { progress } messages meanwhile
//   camera view key|drag|reset|set
//                            the view after a key, a drag, back to the chapter's, or one
//                            typed; the view, or a problem
//   compare index width height rgba
//                            a reader's image of the figure compared with ours as
//                            cgfs-compare compares: verdict, text, difference image and
//                            first differing pixel (program/web/web_entry.cpp)
// A page that wants a draw stopped ends the worker and makes a new one.
'use strict';

let lastProgress = 0;
const chapter = self[self.CGFS_MODULE]({
  // A long figure's progress (the business card's tiles), at most ten times a second.
  onProgress(fraction) {
    const now = performance.now();
    if (now - lastProgress > 100 || fraction >= 1) {
      lastProgress = now;
      postMessage({ progress: fraction });
    }
  },
});

function Text(module, pointer) { return module.UTF8ToString(pointer); }

function SetView(module, view) {
  if (view === undefined) return true;
  const text = module.allocateUTF8(view);
  const ok = module._SetView(text);
  module._free(text);
  return ok;
}

function Pixels(module, bytes) {
  return new Uint8ClampedArray(module.HEAPU8.buffer, module._Pixels(), bytes).slice();
}

const operations = {
  describe(module) {
    const figures = [];
    for (let i = 0; i < module._FigureCount(); ++i) {
      figures.push({ name: Text(module, module._FigureName(i)), caption: Text(module, module._FigureCaption(i)),
        hasCamera: module._FigureHasCamera(i) === 1, costPartner: module._FigureCostPartner(i),
        hasCostView: module._FigureHasCostView(i) === 1 });
    }
    return { figures, settle: module._SettleMilliseconds(), view: Text(module, module._ViewText()) };
  },

  draw(module, { index, width, height, full, view }) {
    if (!SetView(module, view)) return { problem: Text(module, module._LastError()) };
    const [w, h] = full ? [width, height] : [module._PreviewSide(width), module._PreviewSide(height)];
    const start = performance.now();
    if (!module._DrawFigure(index, w, h)) return { problem: Text(module, module._LastError()) };
    const milliseconds = performance.now() - start;
    const pixels = Pixels(module, w * h * 4);
    const measured = Text(module, module._FigureMeasured(index));
    return { answer: { pixels, width: w, height: h, milliseconds, measured }, transfer: [pixels.buffer] };
  },

  camera(module, { view, key, drag, reset, set }) {
    if (set !== undefined) {
      if (!SetView(module, set)) return { problem: Text(module, module._LastError()) };
    } else {
      SetView(module, view);
      if (key !== undefined) module._PressCameraKey(key);
      if (drag !== undefined) module._DragCamera(drag[0], drag[1]);
      if (reset) module._ResetView();
    }
    return { view: Text(module, module._ViewText()) };
  },

  compare(module, { index, width, height, rgba }) {
    const bytes = width * height * 4;
    const at = module._malloc(bytes);
    module.HEAPU8.set(rgba, at);
    const verdict = module._CompareWithFigure(index, width, height, at);
    module._free(at);
    if (verdict < 0) return { problem: Text(module, module._LastError()) };
    const difference = Pixels(module, bytes);
    return { answer: { passed: verdict === 1, text: Text(module, module._ComparisonText()), difference,
      column: module._DifferingColumn(), row: module._DifferingRow() }, transfer: [difference.buffer] };
  },
};

onmessage = async ({ data }) => {
  const module = await chapter;
  let result;
  try {
    result = operations[data.op](module, data);
  } catch (error) {
    result = { problem: String(error?.message ?? error) };
  }
  const { answer, transfer = [] } = result.answer ? result : { answer: result };
  postMessage({ id: data.id, ...answer }, transfer);
};
