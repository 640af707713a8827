// Textures that show a parameterization on the surface: one parameter unit is one checker square,
// or one cell of a grid whose lines are the integer isolines u = k and v = k.
import { DataTexture, LinearFilter, LinearMipmapLinearFilter, RepeatWrapping, SRGBColorSpace } from 'three';

const SIZE = 64; // texels along each side of a tile
const LIGHT = [0xea, 0xd9, 0xb8];
const DARK = [0x6e, 0x58, 0x3e];
const PAPER = [0xd9, 0xc3, 0xa0]; // the surface colour of viewer.js
const INK = [0x2b, 0x22, 0x18];
const GRID_LINE = 3; // texels on each side of an isoline

/** The kinds of texture by name: texels of one tile (RGBA, size x size) and the units it spans. */
export const UV_TEXTURES = Object.freeze({
  checker: { units: 2, texels: () => checkerTexels(SIZE) },
  grid: { units: 1, texels: () => gridTexels(SIZE, GRID_LINE) },
});

/** A 2 x 2 checker tile of size x size texels (RGBA), light squares on the diagonal. */
export function checkerTexels(size) {
  const half = size / 2;
  return fillTexels(size, (x, y) => ((x < half) === (y < half) ? LIGHT : DARK));
}

/** A grid cell of size x size texels (RGBA) whose border, `line` texels wide on each side, is ink. */
export function gridTexels(size, line) {
  const onLine = (i) => i < line || i >= size - line;
  return fillTexels(size, (x, y) => (onLine(x) || onLine(y) ? INK : PAPER));
}

function fillTexels(size, colorAt) {
  const texels = new Uint8Array(4 * size * size);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) texels.set([...colorAt(x, y), 255], 4 * (y * size + x));
  }
  return texels;
}

const made = new Map();

/** The three.js texture of a kind of UV_TEXTURES, made once, repeating once per `units`. */
export function uvTexture(kind, anisotropy) {
  if (!made.has(kind)) {
    const { units, texels } = UV_TEXTURES[kind];
    const texture = new DataTexture(texels(), SIZE, SIZE);
    texture.colorSpace = SRGBColorSpace;
    texture.wrapS = texture.wrapT = RepeatWrapping;
    texture.magFilter = LinearFilter;
    texture.minFilter = LinearMipmapLinearFilter;
    texture.generateMipmaps = true;
    texture.anisotropy = anisotropy;
    texture.repeat.set(1 / units, 1 / units);
    texture.needsUpdate = true;
    made.set(kind, texture);
  }
  return made.get(kind);
}
