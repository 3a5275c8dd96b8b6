// The time bar under the map: the slider, Play and "follow the live run".

import { setDisplayTime, setFollow } from './render.js';
import { state } from './store.js';
import { $ } from './util.js';

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
  const max = Number($('time').max);
  if (state.displayT >= max) setDisplayTime(0);
  let last = performance.now();
  state.playing = setInterval(() => {
    const now = performance.now();
    const t = state.displayT + (now - last) / 1000;
    last = now;
    setDisplayTime(Math.min(t, max));
    if (t >= max) togglePlay();
  }, 100);
  button.textContent = 'Pause';
  button.setAttribute('aria-pressed', 'true');
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
}
