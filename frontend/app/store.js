// The console's one store of state. Every module reads and changes the console's
// state here; `ui` holds the long-lived widgets (map, charts, scenario editor) once
// main.js has made them, and `emit`/`on` tell other modules that something changed.

export const state = {
  plan: null, // plan job {id, status, plan, scenario, ...}
  waitingPlan: null, // id of the plan being computed
  mission: null, // latest mission record
  shown: null, // run on the map: {id, live, rows, t0, loading, buffer}
  telemetry: null, // latest telemetry row
  monitor: null, // the plan monitor's latest assessment of the running plan
  displayT: 0,
  follow: true,
  playing: null,
  liveMessages: 0,
};

/** Work for the next animation frame (render.js draws it). */
export const pending = { rows: [], boat: false, time: false, fromLive: false };

/** The widgets, set once by main.js. */
export const ui = { map: null, charts: null, editor: null };

const listeners = new Map();

/** Call `fn(payload)` on every `emit(event, payload)`. */
export function on(event, fn) {
  if (!listeners.has(event)) listeners.set(event, []);
  listeners.get(event).push(fn);
}

export function emit(event, payload) {
  for (const fn of listeners.get(event) ?? []) fn(payload);
}
