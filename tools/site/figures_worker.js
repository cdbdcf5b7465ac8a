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
//                            cgfs-compare compares: verdict, text, difference image,
//                            what its colours mean and the first differing pixel
//                            (program/web/web_entry.cpp)
//   options files words      the chapter's figures made anew with the options a command
//                            line would give (words: --model house.obj), the files they
//                            name put where the chapter's code reads them; the lines
//                            the program would print (its warnings, or why not) and
//                            the figures, as describe gives them
// A page that wants a draw stopped ends the worker and makes a new one.
"use strict";

let lastProgress = 0;
let said = null; // what the chapter's code prints on its standard error, while heard
const chapter = self[self.CGFS_MODULE]({
  printErr(line) {
    if (said) said.push(line);
    else console.error(line);
  },
  // A long figure's progress (the business card's tiles), at most ten times a second.
  onProgress(fraction) {
    const now = performance.now();
    if (now - lastProgress > 100 || fraction >= 1) {
      lastProgress = now;
      postMessage({ progress: fraction });
    }
  },
});

function textAt(module, pointer) {
  return module.UTF8ToString(pointer);
}

function setView(module, view) {
  if (view === undefined) return true;
  const text = module.allocateUTF8(view);
  const ok = module._SetView(text);
  module._free(text);
  return ok;
}

function copyPixels(module, bytes) {
  return new Uint8ClampedArray(module.HEAPU8.buffer, module._Pixels(), bytes).slice();
}

// The largest image the page decodes for the chapter's code: what its readers accept
// (program/src/image_decoders.h).
const kMaxPixels = 4096 * 4096;

// A file for the chapter's code: as it is, but a PNG or JPEG image, which the page's
// build cannot decode (no libpng or libjpeg in it), decoded by the browser and given as
// a binary PPM, which the chapter's image reader reads (program/web/image_decoders_web.cpp).
// One larger than the readers accept is given as the header alone, which they refuse
// by its size as they refuse the file natively; one the browser cannot decode, as it is.
// Alpha is dropped, as the native readers drop it (the canvas keeps colours multiplied
// by alpha, so a half-transparent texel may differ from libpng's by one).
async function forTheChapter(bytes) {
  const png = [0x89, 0x50, 0x4e, 0x47],
    jpeg = [0xff, 0xd8, 0xff];
  const starts = (magic) => magic.every((byte, i) => bytes[i] === byte);
  if (!starts(png) && !starts(jpeg)) return bytes;
  let bitmap;
  try {
    bitmap = await createImageBitmap(new Blob([bytes]), {
      colorSpaceConversion: "none",
      premultiplyAlpha: "none",
    });
  } catch {
    return bytes;
  }
  const { width, height } = bitmap;
  const header = new TextEncoder().encode(`P6\n${width} ${height}\n255\n`);
  if (width * height > kMaxPixels) return header;
  const canvas = new OffscreenCanvas(width, height);
  const context = canvas.getContext("2d");
  context.drawImage(bitmap, 0, 0);
  const rgba = context.getImageData(0, 0, width, height).data;
  const ppm = new Uint8Array(header.length + width * height * 3);
  ppm.set(header);
  for (let from = 0, to = header.length; from < rgba.length; from += 4, to += 3) {
    ppm[to] = rgba[from];
    ppm[to + 1] = rgba[from + 1];
    ppm[to + 2] = rgba[from + 2];
  }
  return ppm;
}

// The folder the reader's files are put in, the working folder of the chapter's code:
// its messages name them as a program run in their folder would.
const kFolder = "/reader";

const operations = {
  describe(module) {
    const figures = [];
    for (let i = 0; i < module._FigureCount(); ++i) {
      figures.push({
        name: textAt(module, module._FigureName(i)),
        caption: textAt(module, module._FigureCaption(i)),
        hasCamera: module._FigureHasCamera(i) === 1,
        costPartner: module._FigureCostPartner(i),
        hasCostView: module._FigureHasCostView(i) === 1,
      });
    }
    return {
      figures,
      settle: module._SettleMilliseconds(),
      view: textAt(module, module._ViewText()),
    };
  },

  draw(module, { index, width, height, full, view }) {
    if (!setView(module, view)) return { problem: textAt(module, module._LastError()) };
    const [w, h] = full
      ? [width, height]
      : [module._PreviewSide(width), module._PreviewSide(height)];
    const start = performance.now();
    if (!module._DrawFigure(index, w, h)) return { problem: textAt(module, module._LastError()) };
    const milliseconds = performance.now() - start;
    const pixels = copyPixels(module, w * h * 4);
    const measured = textAt(module, module._FigureMeasured(index));
    return {
      answer: { pixels, width: w, height: h, milliseconds, measured },
      transfer: [pixels.buffer],
    };
  },

  camera(module, { view, key, drag, reset, set }) {
    if (set !== undefined) {
      if (!setView(module, set)) return { problem: textAt(module, module._LastError()) };
    } else {
      setView(module, view);
      if (key !== undefined) module._PressCameraKey(key);
      if (drag !== undefined) module._DragCamera(drag[0], drag[1]);
      if (reset) module._ResetView();
    }
    return { view: textAt(module, module._ViewText()) };
  },

  compare(module, { index, width, height, rgba }) {
    const bytes = width * height * 4;
    const at = module._malloc(bytes);
    module.HEAPU8.set(rgba, at);
    const verdict = module._CompareWithFigure(index, width, height, at);
    module._free(at);
    if (verdict < 0) return { problem: textAt(module, module._LastError()) };
    const difference = copyPixels(module, bytes);
    return {
      answer: {
        passed: verdict === 1,
        text: textAt(module, module._ComparisonText()),
        difference,
        colours: textAt(module, module._DifferenceColours())
          .trim()
          .split("\n")
          .map((line) => {
            const [, rgb, name, meaning] = /^(\S+) ([^:]+): (.*)$/.exec(line);
            return { rgb: `rgb(${rgb})`, name, meaning };
          }),
        column: module._DifferingColumn(),
        row: module._DifferingRow(),
      },
      transfer: [difference.buffer],
    };
  },
};

operations.options = async (module, { files = [], words = [] }) => {
  const { FS } = module;
  if (!FS.analyzePath(kFolder).exists) FS.mkdir(kFolder);
  for (const name of FS.readdir(kFolder)) {
    if (name !== "." && name !== "..") FS.unlink(`${kFolder}/${name}`);
  }
  FS.chdir(kFolder);
  for (const { name, bytes } of files) {
    // A name is a word of the command line (one to a line) and a file of one folder.
    if (name === "" || name === "." || name === ".." || /[/\n]/.test(name)) {
      return { problem: `${JSON.stringify(name)} cannot be a file's name here` };
    }
    FS.writeFile(`${kFolder}/${name}`, await forTheChapter(new Uint8Array(bytes)));
  }
  said = [];
  const text = module.allocateUTF8(words.join("\n"));
  const status = module._UseOptions(text);
  module._free(text);
  const lines = said;
  said = null;
  return { status, lines, ...operations.describe(module) };
};

async function answerRequest(data) {
  const module = await chapter;
  let result;
  try {
    result = await operations[data.op](module, data);
  } catch (error) {
    result = { problem: String(error?.message ?? error) };
  }
  const { answer, transfer = [] } = result.answer ? result : { answer: result };
  postMessage({ id: data.id, ...answer }, transfer);
}

// The requests answered in the order they came, each once the one before is done (the
// options' images are decoded asynchronously: a draw asked for meanwhile waits for them).
let answered = Promise.resolve();
onmessage = ({ data }) => {
  answered = answered.then(() => answerRequest(data));
};
