// What the slider timing tools (slider_timing.js, remesh_slider_timing.js) share: reading the
// page's times, releasing a slider in the page and timing what follows, the summary line.

/** Milliseconds from the page's "12 ms" / "1.2 s". */
export function milliseconds(text) {
  const match = /^([\d.]+) (m?s)$/.exec(text.trim());
  if (!match) throw new Error(`not a time: "${text}"`);
  return Number(match[1]) * (match[2] === 'ms' ? 1 : 1000);
}

// In the page (page.evaluate): the slider [data-role=<slider>] set to `value` and released (its
// input and change events). Resolves with the milliseconds until the figure `key` of
// [data-role=<figures>] showed `shown`, and until the frame after it was drawn; null when it shows
// that already (nothing to redo).
export function releaseSliderAt({ slider, figures, key, value, shown }) {
  const input = document.querySelector(`[data-role=${slider}]`);
  const panel = document.querySelector(`[data-role=${figures}]`);
  const shows = () => panel.querySelector(`[data-figure=${key}]`)?.textContent === shown;
  if (shows()) return null;
  return new Promise((resolve) => {
    const start = performance.now();
    const observer = new MutationObserver(() => {
      if (!shows()) return;
      observer.disconnect();
      const shownAfter = performance.now() - start;
      requestAnimationFrame(() =>
        requestAnimationFrame(() => resolve({ shown: shownAfter, drawn: performance.now() - start })),
      );
    });
    observer.observe(panel, { childList: true, subtree: true, characterData: true });
    input.value = String(value);
    input.dispatchEvent(new Event('input', { bubbles: true }));
    input.dispatchEvent(new Event('change', { bubbles: true }));
  });
}

/** "label: median M ms, largest L ms, S of N at <limit> ms or more". */
export function summary(label, times, limitMs) {
  const sorted = [...times].sort((a, b) => a - b);
  const slow = sorted.filter((t) => t >= limitMs).length;
  return `${label}: median ${sorted[sorted.length >> 1].toFixed(0)} ms, largest ${sorted.at(-1).toFixed(0)} ms, ${slow} of ${sorted.length} at ${limitMs} ms or more`;
}
