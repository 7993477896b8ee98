/*
 * arrow_cloud.js: thousands of arrows of one colour (amcl's particle cloud) drawn as one picture.
 *
 * Each arrow is stroked once per heading (HEADINGS of them) on a small canvas; the pixels it covers and their
 * coverage (alpha) are kept. A cloud is then the union of those masks placed at each arrow's whole pixel (the
 * greatest coverage where arrows overlap), written into one ImageData (of the rectangle the arrows cover) by plain
 * JavaScript and copied onto the canvas as one image. Stroking each arrow as a path made the canvas rasterise 3000 anti-aliased paths on the
 * page's main thread: 38-129 ms per cloud (median with the canvas flushed, load 9-10), against 5-16 ms for this in
 * the same minutes (a copy of a small canvas per arrow: 26-113 ms), while state frames waited behind it. The heading
 * is off by 2 degrees at most, the place by half a pixel; inside an arrow the colour is exact.
 */
const HEADINGS = 90;

export class ArrowCloud {
  /** `rgb`: [r, g, b] 0-255; `strokeArrow(ctx, [x, y], yaw, lengthPx)` strokes one arrow from the canvas point
   *  [x, y] (its tail) in that colour. */
  constructor(rgb, strokeArrow) {
    this.rgb = rgb;
    this.strokeArrow = strokeArrow;
    this.masks = null;          // {lengthPx, centre, headings: [{offsets, dx, dy, alphas}]}
    this.picture = null;        // {canvas, alpha: coverage per pixel, 0 outside the cloud being drawn}
  }

  /** Draws the arrows at `poses` (x, y, yaw triples in a Float32Array), each `lengthPx` long, where `toPixel(x, y)`
   *  puts them on `ctx`'s canvas (its current transform applies to the picture as a whole). */
  draw(ctx, poses, lengthPx, toPixel) {
    const {width, height} = ctx.canvas;
    const {centre, headings} = this.masksFor(lengthPx);
    const {canvas, alpha} = this.pictureFor(width, height);
    const step = HEADINGS / (2 * Math.PI);
    let [left, top, right, bottom] = [width, height, -1, -1];   // the pixels the arrows cover, at most
    for (let i = 0; i + 2 < poses.length; i += 3) {
      const [fx, fy] = toPixel(poses[i], poses[i + 1]);
      const px = Math.round(fx);
      const py = Math.round(fy);
      const mask = headings[((Math.round(poses[i + 2] * step) % HEADINGS) + HEADINGS) % HEADINGS];
      if (px >= centre && py >= centre && px + centre < width && py + centre < height) {
        const base = py * width + px;
        for (let k = 0; k < mask.offsets.length; k++) {
          const p = base + mask.offsets[k];
          if (mask.alphas[k] > alpha[p]) alpha[p] = mask.alphas[k];
        }
      } else {
        for (let k = 0; k < mask.offsets.length; k++) {     // at the edge: only the pixels on the canvas
          const x = px + mask.dx[k];
          const y = py + mask.dy[k];
          const p = y * width + x;
          if (x >= 0 && y >= 0 && x < width && y < height && mask.alphas[k] > alpha[p]) alpha[p] = mask.alphas[k];
        }
      }
      left = Math.min(left, px - centre);
      top = Math.min(top, py - centre);
      right = Math.max(right, px + centre);
      bottom = Math.max(bottom, py + centre);
    }
    [left, top, right, bottom] = [Math.max(left, 0), Math.max(top, 0), Math.min(right, width - 1),
      Math.min(bottom, height - 1)];
    if (right < left || bottom < top) return;
    // Only the rectangle the arrows cover is turned into colour and copied (a converged cloud is a few metres).
    const w = right - left + 1;
    const h = bottom - top + 1;
    const picture = canvas.getContext('2d');
    const image = picture.createImageData(w, h);
    const pixels = new Uint32Array(image.data.buffer);
    const [r, g, b] = this.rgb;
    const colour = (b << 16) | (g << 8) | r;    // ImageData is R, G, B, A bytes: little-endian words
    for (let y = 0; y < h; y++) {
      const row = (top + y) * width + left;
      for (let x = 0; x < w; x++) {
        const a = alpha[row + x];
        if (a) pixels[y * w + x] = ((a << 24) | colour) >>> 0;
      }
      alpha.fill(0, row, row + w);             // clean for the next cloud
    }
    picture.putImageData(image, left, top);
    ctx.drawImage(canvas, left, top, w, h, left, top, w, h);
  }

  /** The pixels of the arrow at each heading, as offsets from its tail's pixel, with their coverage. */
  masksFor(lengthPx) {
    if (this.masks && this.masks.lengthPx === lengthPx) return this.masks;
    const centre = Math.ceil(lengthPx) + 2;
    const size = 2 * centre;
    const scratch = document.createElement('canvas');
    scratch.width = scratch.height = size;
    const ctx = scratch.getContext('2d', {willReadFrequently: true});
    const headings = [];
    for (let heading = 0; heading < HEADINGS; heading++) {
      ctx.clearRect(0, 0, size, size);
      // The tail on a pixel corner: a 2 px shaft covers whole pixels, as an arrow drawn at whole pixels does.
      this.strokeArrow(ctx, [centre, centre], heading * 2 * Math.PI / HEADINGS, lengthPx);
      const data = ctx.getImageData(0, 0, size, size).data;
      const dx = [];
      const dy = [];
      const alphas = [];
      for (let y = 0; y < size; y++) {
        for (let x = 0; x < size; x++) {
          const a = data[(y * size + x) * 4 + 3];
          if (a === 0) continue;
          dx.push(x - centre);
          dy.push(y - centre);
          alphas.push(a);
        }
      }
      headings.push({dx: Int16Array.from(dx), dy: Int16Array.from(dy), alphas: Uint8Array.from(alphas),
        offsets: null});
    }
    this.masks = {lengthPx, centre, headings, width: null};
    return this.masks;
  }

  /** The picture the cloud is written into and its coverage, the size of the canvas it is drawn on (the masks'
   *  offsets follow its width). */
  pictureFor(width, height) {
    if (!this.picture || this.picture.canvas.width !== width || this.picture.canvas.height !== height) {
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height;
      this.picture = {canvas, alpha: new Uint8Array(width * height)};
    }
    if (this.masks.width !== width) {
      for (const mask of this.masks.headings) mask.offsets = Int32Array.from(mask.dx, (x, k) => mask.dy[k] * width + x);
      this.masks.width = width;
    }
    return this.picture;
  }
}
