// The index page (made by make_site.py): a small picture of each chapter's opening
// figure, drawn as the page loads by the chapter's own C++ compiled to WebAssembly, in a
// worker (figures_client.js), so that the page scrolls while they are drawn: at the
// figure's own size, since the rasterizer chapters draw in canvas pixels, then shrunk;
// one chapter after the other. Under each, how the reader's own code of the chapter
// fared in its last check on the chapter's page, where there was one.
"use strict";

// Shrinks RGBA pixels by a whole factor, each small pixel the darkest of the block
// it covers, channel by channel: a line one pixel wide stays as dark as it was
// (averaged, it would fade into the white).
function shrink(pixels, width, height, factor) {
  const [small_width, small_height] = [Math.floor(width / factor), Math.floor(height / factor)];
  const small = new Uint8ClampedArray(small_width * small_height * 4).fill(255);
  for (let y = 0; y < small_height * factor; ++y) {
    for (let x = 0; x < small_width * factor; ++x) {
      const from = (y * width + x) * 4;
      const to = (Math.floor(y / factor) * small_width + Math.floor(x / factor)) * 4;
      for (let channel = 0; channel < 3; ++channel) {
        small[to + channel] = Math.min(small[to + channel], pixels[from + channel]);
      }
    }
  }
  return new ImageData(small, small_width, small_height);
}

async function drawThumbnail(canvas) {
  const worker = new FiguresWorker(canvas.dataset.module, CGFS_FIGURES_OF[canvas.dataset.chapter]);
  try {
    const { figures, problem } = await worker.request({ op: "describe" });
    if (problem) throw new Error(problem);
    const index = Math.max(
      0,
      figures.findIndex((figure) => figure.name === canvas.dataset.opening),
    );
    const name = figures[index].name;
    const [width, height] = JSON.parse(canvas.dataset.sizes)[name] ?? [600, 600]; // its golden image's
    const frame = await worker.request({ op: "draw", index, width, height, full: true });
    if (frame.problem) throw new Error(frame.problem);
    const small = shrink(frame.pixels, width, height, Math.ceil(width / canvas.width));
    canvas.width = small.width;
    canvas.height = small.height;
    canvas.getContext("2d").putImageData(small, 0, 0);
    canvas.title = name;
  } catch (error) {
    canvas.title = String(error.message ?? error);
  } finally {
    worker.worker.terminate();
  }
}

async function drawThumbnails() {
  for (const canvas of document.querySelectorAll("canvas.thumbnail")) await drawThumbnail(canvas);
  document.body.dataset.thumbnails = "drawn";
}

// Under each chapter's picture, how the reader's own code of it fared in its last full
// check on the chapter's page (yourcode.js keeps it in this browser's storage).
function showProgress() {
  for (const canvas of document.querySelectorAll("canvas.thumbnail")) {
    let kept = null;
    try {
      kept = JSON.parse(localStorage.getItem(`cgfs-progress:${canvas.dataset.chapter}`));
    } catch {
      // storage refused, or not what yourcode.js keeps: nothing to show
    }
    if (
      !kept ||
      !Array.isArray(kept.passed) ||
      !Array.isArray(kept.failed) ||
      !Array.isArray(kept.unwritten)
    )
      continue;
    const total = kept.passed.length + kept.failed.length + kept.unwritten.length;
    const line = document.createElement("p");
    line.className = "progress";
    line.dataset.done = kept.passed.length === total ? "yes" : "no";
    line.textContent =
      `yours (${kept.language === "python" ? "Python" : "JavaScript"}): ` +
      `${kept.passed.length === total ? "✓ " : ""}${kept.passed.length} of ${total} functions pass` +
      (kept.failed.length ? `; to fix: ${kept.failed.join(", ")}` : "") +
      (kept.unwritten.length ? `; to write: ${kept.unwritten.join(", ")}` : "");
    canvas.closest("td").append(line);
  }
}

showProgress();
drawThumbnails();
