// Small helpers shared by the console's modules.

export const $ = (id) => document.getElementById(id);

export function fmt(v, digits = 1) {
  return v == null || Number.isNaN(v) ? '–' : Number(v).toFixed(digits);
}

/** Show an error (or clear it with null) in the `${where}-error` element. */
export function showError(where, err) {
  const el = $(`${where}-error`);
  el.textContent = err ? (err.message ?? String(err)) : '';
}

export const sleep = (ms) => new Promise((resolve) => { setTimeout(resolve, ms); });

/** Let the browser paint and handle input between start-up steps (no long tasks). */
export const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });

export function setPill(el, text, kind) {
  el.textContent = text;
  el.className = `pill pill-${kind}`;
}
