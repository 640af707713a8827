// The alpha slider's positions solved ahead while the worker is idle (the core's presolve_layout()):
// a move to a presolved position then costs one layout and no P1. Fertility (1,670 edges, 50,510
// conflicts) in wasm under node: the 40 other positions presolved in 3.0 s after the first layout
// (the slowest, alpha 0, 383 ms); in the page afterwards every move showed its layout within 70 ms
// (median 31 ms), where cold moves took up to 405 ms (tests/browser/slider_timing.js --wait).

/** The most positions a page may ask for (the slider has 41). */
export const MAX_PRESOLVE_POSITIONS = 1000;

/**
 * A presolve that took longer than this stops the queue: the worker cannot take a request while one
 * runs, so a graph this slow to solve is not presolved (a request waits at most this long for it).
 */
export const MAX_PRESOLVE_SECONDS = 1;

/**
 * The alphas to presolve, nearest to `from` first (the smaller first of two as far), each once;
 * `from` itself is solved. Anything but an array of at most MAX_PRESOLVE_POSITIONS finite numbers
 * >= 0 gives none: the list comes from the page and is only a hint.
 */
export function presolveOrder(alphas, from) {
  if (!Array.isArray(alphas) || alphas.length > MAX_PRESOLVE_POSITIONS) return [];
  if (!alphas.every((a) => typeof a === 'number' && Number.isFinite(a) && a >= 0)) return [];
  const distinct = [...new Set(alphas)].filter((a) => a !== from);
  return distinct.sort((a, b) => Math.abs(a - from) - Math.abs(b - from) || a - b);
}

/**
 * Runs presolve(alpha) for each alpha of `order`, one per macrotask, so that a request that comes
 * in is taken between two of them. Stops when stillWanted() turns false, when presolve throws or
 * returns false (no proven optimum within the limits), or when one took longer than
 * MAX_PRESOLVE_SECONDS. Resolves with the number of alphas presolved. `now` returns milliseconds.
 */
export function presolveInTurn(order, presolve, stillWanted, { now = () => performance.now(), yieldTurn = nextTurn } = {}) {
  return (async () => {
    let done = 0;
    for (const alpha of order) {
      await yieldTurn();
      if (!stillWanted()) break;
      const started = now();
      let solved = false;
      try {
        solved = presolve(alpha);
      } catch {
        break; // the request for this alpha, if it comes, reports the error
      }
      if (!solved) break;
      done += 1;
      if ((now() - started) / 1000 > MAX_PRESOLVE_SECONDS) break;
    }
    return done;
  })();
}

const nextTurn = () => new Promise((resolve) => setTimeout(resolve, 0));
