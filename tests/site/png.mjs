// Reads a PNG file as the project writes them (8 bits, RGB or RGBA, not interlaced)
// into RGBA bytes, as a canvas's ImageData holds them: enough to compare a page's
// canvas with a golden image (tests/site/check_site.mjs) without a package.
import { createHash } from "node:crypto";
import { readFileSync, writeFileSync } from "node:fs";
import { deflateSync, inflateSync } from "node:zlib";

// PNG's Paeth predictor: of the left, upper and upper-left bytes, the one nearest
// to left + upper - upper-left.
function paeth(left, up, upLeft) {
  const estimate = left + up - upLeft;
  const [toLeft, toUp, toUpLeft] = [left, up, upLeft].map((v) => Math.abs(estimate - v));
  return toLeft <= toUp && toLeft <= toUpLeft ? left : toUp <= toUpLeft ? up : upLeft;
}

// A PNG file as [width, height, SHA-256 of its RGBA pixels], as Browser.canvasDigest
// (browser.mjs) gives a page's canvas.
export function pngDigest(path) {
  const image = readPng(path);
  return [image.width, image.height, createHash("sha256").update(image.rgba).digest("hex")];
}

export function readPng(path) {
  const file = readFileSync(path);
  let width = 0,
    height = 0,
    channels = 0;
  const compressed = [];
  for (let at = 8; at < file.length;) {
    const length = file.readUInt32BE(at);
    const type = file.toString("latin1", at + 4, at + 8);
    const body = file.subarray(at + 8, at + 8 + length);
    if (type === "IHDR") {
      [width, height] = [body.readUInt32BE(0), body.readUInt32BE(4)];
      const [depth, colour, interlace] = [body[8], body[9], body[12]];
      if (depth !== 8 || interlace !== 0 || (colour !== 2 && colour !== 6)) {
        throw new Error(`${path}: not an 8-bit RGB or RGBA PNG without interlacing`);
      }
      channels = colour === 2 ? 3 : 4;
    } else if (type === "IDAT") {
      compressed.push(body);
    }
    at += 12 + length;
  }
  const filtered = inflateSync(Buffer.concat(compressed));
  const stride = width * channels;
  const rgba = Buffer.alloc(width * height * 4);
  let above = Buffer.alloc(stride);
  for (let y = 0; y < height; ++y) {
    const filter = filtered[y * (stride + 1)];
    const row = Buffer.from(filtered.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; ++i) {
      const left = i >= channels ? row[i - channels] : 0;
      const upLeft = i >= channels ? above[i - channels] : 0;
      const predicted = [0, left, above[i], (left + above[i]) >> 1, paeth(left, above[i], upLeft)];
      row[i] = (row[i] + predicted[filter]) & 255;
    }
    for (let x = 0; x < width; ++x) {
      const to = (y * width + x) * 4;
      row.copy(rgba, to, x * channels, x * channels + 3);
      rgba[to + 3] = channels === 4 ? row[x * channels + 3] : 255;
    }
    above = row;
  }
  return { width, height, rgba };
}

// CRC-32 of PNG's chunks (ISO 3309), a byte at a time.
function crc32(bytes) {
  let crc = ~0;
  for (const byte of bytes) {
    crc ^= byte;
    for (let bit = 0; bit < 8; ++bit) crc = (crc >>> 1) ^ (0xedb88320 & -(crc & 1));
  }
  return ~crc >>> 0;
}

// Writes RGBA bytes as an 8-bit RGBA PNG (every row filtered with None): a page's
// picture, for the native tools to read (check_your_code.mjs hands one to cgfs-compare).
export function writePng(path, width, height, rgba) {
  const chunk = (type, body) => {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(body.length, 0);
    head.write(type, 4, "latin1");
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), body])), 0);
    return Buffer.concat([head, body, crc]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 6, 0, 0, 0], 8);
  const rows = Buffer.alloc(height * (width * 4 + 1));
  for (let y = 0; y < height; ++y)
    rows.set(rgba.subarray(y * width * 4, (y + 1) * width * 4), y * (width * 4 + 1) + 1);
  writeFileSync(
    path,
    Buffer.concat([
      Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
      chunk("IHDR", header),
      chunk("IDAT", deflateSync(rows)),
      chunk("IEND", Buffer.alloc(0)),
    ]),
  );
}
