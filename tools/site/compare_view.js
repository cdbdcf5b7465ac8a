// The comparison a draw in the "Your code" panel gives (yourcode.js): ours, the reader's
// and their difference side by side, or one picture with a slider between ours and
// theirs (and a blink); the difference's colours in a legend (the comparison library's,
// kDifferenceColours, through the chapter's WebAssembly); and a magnifier on one pixel,
// the first differing one at first, any other a click away.
"use strict";

const kZoomPixels = 15; // the magnifier shows this many pixels across
const kZoomScale = 9; // each drawn this many screen pixels wide
const kBlinkMilliseconds = 600;

class ComparisonView {
  // On the page's elements (make_site.py's your_code_panel), by their ids.
  constructor() {
    const $ = (id) => document.getElementById(id);
    this.canvases = {
      ours: $("code-ours"),
      yours: $("code-yours"),
      difference: $("code-difference"),
    };
    this.overlay = $("code-overlay");
    this.wipe = $("code-wipe");
    this.blink = $("code-blink");
    this.blinkTimer = null;
    this.blinkShowsYours = false;
    this.images = null;
    for (const radio of document.querySelectorAll('input[name="code-view"]')) {
      radio.addEventListener("change", () => this.showView(radio.value));
    }
    this.wipe.addEventListener("input", () => this.drawOverlay());
    this.blink.addEventListener("change", () => this.blink(this.blink.checked));
    for (const canvas of [...Object.values(this.canvases), this.overlay]) {
      canvas.addEventListener("click", (event) => this.zoomAtClick(canvas, event));
    }
  }

  // ours, yours, difference: RGBA bytes of width x height; first: the first differing
  // pixel ({ column, row }, column -1 when none); colours: the difference's legend.
  show({ ours, yours, difference, width, height, first, colours }) {
    this.images = { ours, yours, difference, width, height };
    for (const [name, pixels] of Object.entries({ ours, yours, difference })) {
      ComparisonView.putOn(this.canvases[name], pixels, width, height);
    }
    if (first.column >= 0) {
      ComparisonView.ring(this.canvases.yours, first.column, first.row);
      ComparisonView.ring(this.canvases.difference, first.column, first.row);
    }
    this.overlay.width = width;
    this.overlay.height = height;
    this.drawOverlay();
    this.showLegend(colours);
    this.zoom(
      first.column >= 0 ? first.column : width >> 1,
      first.column >= 0 ? first.row : height >> 1,
      first.column >= 0 ? "the first differing pixel" : "the middle pixel (none differs)",
    );
  }

  static putOn(canvas, pixels, width, height) {
    canvas.width = width;
    canvas.height = height;
    canvas
      .getContext("2d")
      .putImageData(new ImageData(new Uint8ClampedArray(pixels), width, height), 0, 0);
  }

  // A ring around a pixel, on a picture.
  static ring(canvas, column, row) {
    const context = canvas.getContext("2d");
    context.lineWidth = Math.max(2, canvas.width / 150);
    for (const [color, radius] of [
      ["#fff", 14],
      ["#e00", 12],
    ]) {
      context.strokeStyle = color;
      context.beginPath();
      context.arc(column + 0.5, row + 0.5, (radius * canvas.width) / 600, 0, 2 * Math.PI);
      context.stroke();
    }
  }

  showView(which) {
    document.getElementById("code-three").hidden = which !== "three";
    document.getElementById("code-one").hidden = which !== "one";
    if (which !== "one") this.blink(false);
  }

  // One picture: the reader's left of the slider, ours right of it; blinking, each in
  // turn, the whole picture.
  drawOverlay() {
    if (!this.images) return;
    const { ours, yours, width, height } = this.images;
    const context = this.overlay.getContext("2d");
    const split =
      this.blinkTimer !== null
        ? this.blinkShowsYours
          ? width
          : 0
        : Math.round((width * Number(this.wipe.value)) / 100);
    const picture = new Uint8ClampedArray(ours);
    for (let row = 0; row < height; ++row) {
      const start = row * width * 4;
      picture.set(yours.subarray(start, start + split * 4), start);
    }
    context.putImageData(new ImageData(picture, width, height), 0, 0);
    if (this.blinkTimer === null && split > 0 && split < width) {
      context.fillStyle = "#fff";
      context.fillRect(split - 1, 0, 2, height);
    }
    document.getElementById("code-one-says").textContent =
      this.blinkTimer !== null
        ? `now: ${this.blinkShowsYours ? "yours" : "ours"}`
        : "yours left of the line, ours right of it";
  }

  blink(on) {
    clearInterval(this.blinkTimer);
    this.blinkTimer = null;
    this.blink.checked = on;
    if (on) {
      this.blinkTimer = setInterval(() => {
        this.blinkShowsYours = !this.blinkShowsYours;
        this.drawOverlay();
      }, kBlinkMilliseconds);
    }
    this.drawOverlay();
  }

  showLegend(colours) {
    const legend = document.getElementById("code-legend");
    legend.replaceChildren(
      ...colours.map(({ rgb, name, meaning }) => {
        const item = document.createElement("li");
        const swatch = document.createElement("span");
        swatch.className = "swatch";
        swatch.style.background = rgb;
        item.append(swatch, `${name}: ${meaning}`);
        return item;
      }),
    );
    const faded = document.createElement("li");
    faded.textContent = "pale grey: ours, where they are the same";
    legend.append(faded);
  }

  zoomAtClick(canvas, event) {
    if (!this.images) return;
    // (offsetX and offsetY are from the picture's corner inside its border)
    const column = Math.floor((event.offsetX * canvas.width) / canvas.clientWidth);
    const row = Math.floor((event.offsetY * canvas.height) / canvas.clientHeight);
    this.zoom(column, row, "the pixel clicked");
  }

  // The magnifier: kZoomPixels across around (column, row) of ours, yours and the
  // difference, the pixel itself outlined, and its two colours in words.
  zoom(column, row, what) {
    const { width, height } = this.images;
    column = Math.min(Math.max(column, 0), width - 1);
    row = Math.min(Math.max(row, 0), height - 1);
    const half = kZoomPixels >> 1;
    const colourAt = (pixels) => {
      const at = (row * width + column) * 4;
      return `rgb(${pixels[at]}, ${pixels[at + 1]}, ${pixels[at + 2]})`;
    };
    for (const name of ["ours", "yours", "difference"]) {
      const canvas = document.getElementById(`code-zoom-${name}`);
      const pixels = this.images[name];
      canvas.width = canvas.height = kZoomPixels * kZoomScale;
      const context = canvas.getContext("2d");
      context.fillStyle = "#fff";
      context.fillRect(0, 0, canvas.width, canvas.height);
      for (let dy = -half; dy <= half; ++dy) {
        for (let dx = -half; dx <= half; ++dx) {
          const x = column + dx;
          const y = row + dy;
          if (x < 0 || y < 0 || x >= width || y >= height) continue;
          const at = (y * width + x) * 4;
          context.fillStyle = `rgb(${pixels[at]}, ${pixels[at + 1]}, ${pixels[at + 2]})`;
          context.fillRect(
            (dx + half) * kZoomScale,
            (dy + half) * kZoomScale,
            kZoomScale,
            kZoomScale,
          );
        }
      }
      // black and white, seen on any colour
      for (const [color, width] of [
        ["#000", 3],
        ["#fff", 1],
      ]) {
        context.lineWidth = width;
        context.strokeStyle = color;
        context.strokeRect(half * kZoomScale, half * kZoomScale, kZoomScale, kZoomScale);
      }
    }
    const where = document.getElementById("code-zoom-where");
    where.textContent =
      `Magnified: ${what}, column ${column}, row ${row} from the top left: ` +
      `ours ${colourAt(this.images.ours)}, yours ${colourAt(this.images.yours)}. Click a picture to look elsewhere.`;
    where.dataset.column = column;
    where.dataset.row = row;
  }
}
