// The index page (made by make_site.py): a small picture of each chapter's first
// figure, drawn as the page loads by the chapter's own C++ compiled to WebAssembly
// (its figures.js), one chapter after the other so that the page stays responsive.
'use strict';

async function DrawThumbnail(canvas) {
  const chapter = await window[canvas.dataset.module]();
  if (!chapter._DrawFigure(0, canvas.width, canvas.height)) {
    canvas.title = chapter.UTF8ToString(chapter._LastError());
    return;
  }
  const bytes = canvas.width * canvas.height * 4;
  const pixels = new Uint8ClampedArray(chapter.HEAPU8.buffer, chapter._Pixels(), bytes);
  canvas.getContext('2d').putImageData(
      new ImageData(new Uint8ClampedArray(pixels), canvas.width, canvas.height), 0, 0);
  canvas.title = chapter.UTF8ToString(chapter._FigureName(0));
}

async function DrawThumbnails() {
  for (const canvas of document.querySelectorAll('canvas.thumbnail')) {
    await DrawThumbnail(canvas);
    await new Promise((resolve) => setTimeout(resolve, 0));  // let the page draw it
  }
  document.body.dataset.thumbnails = 'drawn';
}

DrawThumbnails();
