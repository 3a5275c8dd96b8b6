// Runs: the runs table, and the run shown on the map and charts (its stored
// telemetry first, then live rows as they come; its plan alongside).

import * as api from './api.js';
import { showPlan } from './plan.js';
import { requestRender, setDisplayTime, setFollow } from './render.js';
import { pending, state, ui } from './store.js';
import { updateTimeRange } from './timebar.js';
import { $, showError } from './util.js';

const EXPORT_FORMATS = ['csv', 'gpx', 'geojson', 'jsonl'];

export function onTelemetry(row, fromLive) {
  state.telemetry = row;
  pending.boat = true;
  pending.fromLive = fromLive;
  if (fromLive) state.liveMessages += 1;
  const shown = state.shown;
  if (row.run != null && (!shown || shown.id !== row.run) && state.follow) {
    showRun(row.run, { live: true });
  }
  if (state.shown && state.shown.id === row.run) addRunRows([row]);
  requestRender();
}

function addRunRows(rows) {
  const shown = state.shown;
  if (shown.loading) {
    shown.buffer.push(...rows);
    return;
  }
  if (!rows.length) return;
  if (shown.t0 === null) shown.t0 = rows[0].boat_time;
  shown.rows.push(...rows);
  pending.rows.push(...rows);
  updateTimeRange();
  if (shown.live && state.follow) {
    setDisplayTime(rows[rows.length - 1].boat_time - shown.t0);
  } else {
    // the slider may have moved while the rows loaded: draw the replayed boat where it is
    setDisplayTime(state.displayT);
  }
}

/** Draw run `id`: its stored telemetry, then live rows as they come; its plan alongside. */
export async function showRun(id, { live }) {
  const shown = { id, live, rows: [], t0: null, loading: true, buffer: [] };
  state.shown = shown;
  ui.map.setTrack([]);
  ui.charts.clearReal();
  pending.rows = [];
  $('track-points').textContent = '0';
  try {
    const [rows, runs] = await Promise.all([api.get(`/api/telemetry?run=${id}`),
      api.get('/api/runs')]);
    if (state.shown !== shown) return;
    const last = rows.length ? rows[rows.length - 1].boat_time : -Infinity;
    const later = shown.buffer.filter((r) => r.boat_time > last);
    shown.loading = false;
    shown.buffer = [];
    addRunRows(rows.concat(later));
    requestRender();
    renderRuns(runs);
    const run = runs.find((r) => r.id === id);
    if (run && run.plan_id && (!state.plan || state.plan.id !== run.plan_id)) {
      const job = await api.get(`/api/plans/${run.plan_id}`);
      // a live run's plan (from the boat, a re-plan) is on the boat: judged against the
      // working scenario it runs with, not its own start
      if (state.shown === shown && shown.live && ui.editor.scenario) {
        job.basisScenario = JSON.parse(JSON.stringify(ui.editor.scenario));
      }
      showPlan(job);
    }
  } catch (err) {
    shown.loading = false;
    showError('runs', err);
  }
}

export async function refreshRuns() {
  try {
    renderRuns(await api.get('/api/runs'));
    showError('runs', null);
  } catch (err) {
    showError('runs', err);
  }
}

function renderRuns(runs) {
  const body = $('run-rows');
  body.replaceChildren(...[...runs].sort((a, b) => b.id - a.id).map((run) => {
    const tr = document.createElement('tr');
    tr.dataset.run = String(run.id);
    const started = run.started_at ? new Date(run.started_at).toLocaleTimeString([],
      { hour: '2-digit', minute: '2-digit', second: '2-digit', hour12: false }) : '–';
    const first = document.createElement('td');
    const show = document.createElement('button');
    show.type = 'button';
    show.className = 'icon';
    show.textContent = `#${run.id}`;
    show.title = `show run ${run.id} on the map and charts`;
    show.setAttribute('aria-label', `show run ${run.id} on the map and charts`);
    show.addEventListener('click', () => {
      setFollow(run.state === 'active');
      showRun(run.id, { live: run.state === 'active' });
    });
    first.append(show);
    tr.append(first);
    for (const text of [run.state, started, String(run.points ?? 0)]) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.append(td);
    }
    const links = document.createElement('td');
    links.className = 'downloads';
    for (const format of EXPORT_FORMATS) {
      const a = document.createElement('a');
      a.href = `/api/telemetry/export?run=${run.id}&format=${format}`;
      a.download = `run-${run.id}.${format === 'jsonl' ? 'jsonl' : format}`;
      a.textContent = format.toUpperCase();
      a.setAttribute('aria-label', `download run ${run.id} as ${format.toUpperCase()}`);
      links.append(a, ' ');
    }
    tr.append(links);
    return tr;
  }));
}
