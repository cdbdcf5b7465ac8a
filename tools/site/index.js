// The index page (made by make_site.py): a small picture of each chapter's first
// figure, drawn as the page loads by the chapter's own C++ compiled to WebAssembly
// (its figures.js) at the figure's own size, since the rasterizer chapters draw in
// canvas pixels; one chapter after the other, so that the page stays responsive.
'use strict';

// Shrinks RGBA pixels by a whole factor, each small pixel the darkest of the block
// it covers, channel by channel: a line one pixel wide stays as dark as it was
// (averaged, it would fade into the white).
function Shrink(pixels, width, height, factor) {
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

async function DrawThumbnail(canvas) {
  const chapter = await window[canvas.dataset.module]();
  const name = chapter.UTF8ToString(chapter._FigureName(0));
  const [width, height] = JSON.parse(canvas.dataset.sizes)[name] ?? [600, 600];  // its golden image's
  if (!chapter._DrawFigure(0, width, height)) {
    canvas.title = chapter.UTF8ToString(chapter._LastError());
    return;
  }
  const pixels = new Uint8ClampedArray(chapter.HEAPU8.buffer, chapter._Pixels(), width * height * 4);
  const small = Shrink(pixels, width, height, Math.ceil(width / canvas.width));
  canvas.width = small.width;
  canvas.height = small.height;
  canvas.getContext('2d').putImageData(small, 0, 0);
  canvas.title = name;
}

async function DrawThumbnails() {
  for (const canvas of document.querySelectorAll('canvas.thumbnail')) {
    await DrawThumbnail(canvas);
    await new Promise((resolve) => setTimeout(resolve, 0));  // let the page draw it
  }
  document.body.dataset.thumbnails = 'drawn';
}

DrawThumbnails();
