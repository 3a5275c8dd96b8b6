// The time bar under the map: the slider, Play and "follow the live run".

import { setDisplayTime, setFollow } from './render.js';
import { on, state, ui } from './store.js';
import { $ } from './util.js';

const PLAY_TICK_MS = 50;

/** Play the time bar from here at the chosen speed (1-20x) up to its end. */
function togglePlay() {
  const button = $('play');
  if (state.playing) {
    clearInterval(state.playing);
    state.playing = null;
    button.textContent = 'Play';
    button.setAttribute('aria-pressed', 'false');
    return;
  }
  setFollow(false);
  const max = () => Number($('time').max);
  if (state.displayT >= max()) setDisplayTime(0);
  let last = performance.now();
  state.playing = setInterval(() => {
    const now = performance.now();
    const rate = Number($('replay-speed').value) || 1;
    const t = state.displayT + ((now - last) / 1000) * rate;
    last = now;
    setDisplayTime(Math.min(t, max()));
    if (t >= max()) togglePlay();
  }, PLAY_TICK_MS);
  button.textContent = 'Pause';
  button.setAttribute('aria-pressed', 'true');
}

/** Index of the last row at or before run time t (rows in boat-time order). */
export function rowAt(rows, t0, t) {
  let lo = 0;
  let hi = rows.length - 1;
  if (hi < 0 || rows[0].boat_time - t0 > t) return -1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (rows[mid].boat_time - t0 <= t) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/** The shown run's boat at the displayed time, unless the live run is being followed. */
function showReplay(t) {
  const shown = state.shown;
  if (!shown || !shown.rows.length || (shown.live && state.follow)) {
    ui.map.setReplayBoat(null);
    return;
  }
  const i = rowAt(shown.rows, shown.t0, t);
  ui.map.setReplayBoat(i < 0 ? null : shown.rows[i]);
}

const PLAN_MARGIN = 1.2; // the slider reaches past the plan's end by this factor

/** The slider covers the plan (with a margin) and the whole shown run, however long. */
export function updateTimeRange() {
  const plan = state.plan?.plan;
  let end = plan ? plan.metrics.duration_s * PLAN_MARGIN : 0;
  const shown = state.shown;
  if (shown && shown.rows.length) {
    end = Math.max(end, shown.rows[shown.rows.length - 1].boat_time - shown.t0);
  }
  if (!plan && !(shown && shown.rows.length)) end = 120;
  const max = String(Math.ceil(end * 10) / 10);
  if ($('time').max !== max) $('time').max = max;
}

export function bindTimebar() {
  $('time').addEventListener('input', (e) => {
    setFollow(false);
    setDisplayTime(Number(e.target.value));
  });
  $('follow').addEventListener('change', (e) => {
    state.follow = e.target.checked;
    const shown = state.shown;
    if (state.follow && shown && shown.rows.length) {
      setDisplayTime(shown.rows[shown.rows.length - 1].boat_time - shown.t0);
    }
  });
  $('play').addEventListener('click', togglePlay);
  on('time', showReplay);
}
