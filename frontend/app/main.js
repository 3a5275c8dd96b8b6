// The operator console: wires the map, charts and controls to the station's
// HTTP API and live websocket (/ws/live). Telemetry is buffered as it arrives
// and drawn once per animation frame; charts redraw at most twice a second.

import * as api from './api.js';
import { TelemetryCharts } from './charts.js';
import { ConsoleMap, planPositionAt } from './map.js';
import { ScenarioEditor } from './scenario.js';

const $ = (id) => document.getElementById(id);
const CHART_EVERY_MS = 500;
const BOAT_POLL_MS = 1000;
const EXPORT_FORMATS = ['csv', 'gpx', 'geojson', 'jsonl'];

const state = {
  plan: null, // plan job {id, status, plan, scenario, ...}
  waitingPlan: null, // id of the plan being computed
  mission: null, // latest mission record
  shown: null, // run on the map: {id, live, rows, t0, loading, buffer}
  telemetry: null, // latest telemetry row
  displayT: 0,
  follow: true,
  playing: null,
  liveMessages: 0,
};
const pending = { rows: [], boat: false, time: false, fromLive: false };
let map;
let charts;
let editor;
let frameRequested = false;
let chartTimer = null;
let lastChartAt = -Infinity;
let firstDrawn = false;
let firstLiveDrawn = false;

function showError(where, err) {
  const el = $(`${where}-error`);
  el.textContent = err ? (err.message ?? String(err)) : '';
}

function fmt(v, digits = 1) {
  return v == null || Number.isNaN(v) ? '–' : Number(v).toFixed(digits);
}

const sleep = (ms) => new Promise((resolve) => { setTimeout(resolve, ms); });

// --- drawing ---------------------------------------------------------------------------

function requestRender() {
  if (frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(render);
}

function render() {
  frameRequested = false;
  if (pending.rows.length) {
    const rows = pending.rows;
    pending.rows = [];
    map.appendTrack(rows);
    charts.appendReal(rows);
    scheduleCharts();
    $('track-points').textContent = String(map.trackLatLngs.length);
  }
  if (pending.boat && state.telemetry) {
    pending.boat = false;
    drawBoat(state.telemetry);
  }
  if (pending.time) {
    pending.time = false;
    map.setDisplayTime(state.displayT);
    $('time').value = String(state.displayT);
    $('time-out').textContent = fmt(state.displayT);
  }
}

function drawBoat(row) {
  map.setBoat(row);
  $('boat-x').textContent = fmt(row.x);
  $('boat-y').textContent = fmt(row.y);
  $('boat-heading').textContent = fmt(row.ramp_heading_deg, 0);
  $('boat-compass').textContent = fmt(row.heading_deg, 0);
  $('boat-speed').textContent = fmt(row.speed, 2);
  $('boat-state').textContent = row.mode ?? '–';
  if (!firstDrawn) {
    firstDrawn = true;
    performance.mark('first-telemetry-drawn');
  }
  if (pending.fromLive && !firstLiveDrawn) {
    firstLiveDrawn = true;
    performance.mark('first-live-telemetry-drawn');
  }
}

/** Redraw the charts now if they have not been drawn for a while, else a little later. */
function scheduleCharts() {
  if (chartTimer !== null) return;
  const wait = Math.max(0, lastChartAt + CHART_EVERY_MS - performance.now());
  chartTimer = setTimeout(() => {
    chartTimer = null;
    lastChartAt = performance.now();
    charts.flush();
  }, wait);
}

function setDisplayTime(t) {
  state.displayT = Math.max(0, t);
  pending.time = true;
  requestRender();
}

// --- runs and telemetry ---------------------------------------------------------------------

function onTelemetry(row, fromLive) {
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
  if (shown.live && state.follow) {
    setDisplayTime(rows[rows.length - 1].boat_time - shown.t0);
  }
}

/** Draw run `id`: its stored telemetry, then live rows as they come; its plan alongside. */
async function showRun(id, { live }) {
  const shown = { id, live, rows: [], t0: null, loading: true, buffer: [] };
  state.shown = shown;
  map.setTrack([]);
  charts.clearReal();
  pending.rows = [];
  $('track-points').textContent = '0';
  try {
    const [rows, runs] = await Promise.all([api.get(`/api/telemetry?run=${id}`), api.get('/api/runs')]);
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
      showPlan(await api.get(`/api/plans/${run.plan_id}`));
    }
  } catch (err) {
    shown.loading = false;
    showError('runs', err);
  }
}

async function refreshRuns() {
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
      state.follow = run.state === 'active';
      $('follow').checked = state.follow;
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

// --- plan -----------------------------------------------------------------------------------

const METRICS = [
  ['fitness', 'fitness (eq. 12)', '', 4],
  ['fit_d', 'Fit_d, length ratio', '', 3],
  ['fit_t', 'Fit_T, time per leg', 's', 2],
  ['fit_ang', 'Fit_ang, turning', '', 3],
  ['fit_mal', 'Fit_mal, offset from axis', 'm', 2],
  ['length_m', 'length', 'm', 1],
  ['duration_s', 'duration', 's', 1],
  ['min_clearance_m', 'min. clearance', 'm', 2],
  ['collision_free', 'collision-free', '', 0],
  ['generations', 'generations', '', 0],
  ['elapsed_s', 'planning time', 's', 3],
];

function showPlan(job) {
  state.plan = job;
  const plan = job.plan;
  map.setPlan(plan, job.scenario.vessel);
  charts.setPlan(plan);
  scheduleCharts();
  const duration = plan.metrics.duration_s;
  map.setHorizon(duration * 1.2);
  map.setScenario(editor.scenario);
  $('time').max = String(Math.ceil(duration * 1.2));
  const dl = $('plan-metrics');
  dl.replaceChildren();
  for (const [key, label, unit, digits] of METRICS) {
    const value = plan.metrics[key];
    if (value === undefined) continue;
    const div = document.createElement('div');
    div.dataset.metric = key;
    const dt = document.createElement('dt');
    dt.textContent = label;
    const dd = document.createElement('dd');
    if (typeof value === 'boolean') dd.textContent = value ? 'yes' : 'no';
    else dd.textContent = `${Number(value).toFixed(digits)}${unit ? ` ${unit}` : ''}`;
    div.append(dt, dd);
    dl.append(div);
  }
  for (const warning of plan.warnings ?? []) {
    const div = document.createElement('div');
    div.className = 'warning';
    div.textContent = warning;
    dl.append(div);
  }
  const [vmin, vmax] = map.speedRange;
  $('speed-min').textContent = fmt(vmin, 1);
  $('speed-max').textContent = fmt(vmax, 1);
  $('speed-legend').hidden = false;
  updateStale();
  setDisplayTime(state.displayT);
}

function updateStale() {
  const stale = Boolean(state.plan) && !editor.matches(state.plan.scenario);
  $('plan-stale').hidden = !stale;
  $('upload').disabled = !state.plan || stale;
}

async function runPlan() {
  showError('plan', null);
  const button = $('plan');
  button.disabled = true;
  const started = performance.now();
  const progress = $('plan-progress');
  try {
    await editor.flush();
    const seedText = $('seed').value.trim();
    const body = seedText === '' ? {} : { seed: Number(seedText) };
    const accepted = await api.post('/api/plans', body);
    state.waitingPlan = accepted.id;
    progress.hidden = false;
    let job;
    for (;;) {
      job = await api.get(`/api/plans/${accepted.id}`);
      const secs = ((performance.now() - started) / 1000).toFixed(1);
      $('plan-progress-text').textContent = `${job.status}, ${secs} s`;
      if (job.status === 'done' || job.status === 'failed') break;
      await sleep(150);
    }
    if (job.status === 'failed') throw new Error(`no plan: ${job.error}`);
    showPlan(job);
  } catch (err) {
    showError('plan', err);
  } finally {
    state.waitingPlan = null;
    progress.hidden = true;
    button.disabled = false;
  }
}

// --- upload and commands ------------------------------------------------------------------

function renderMission(mission) {
  state.mission = mission;
  if (!mission) return;
  const { sent, acked, total } = mission.progress;
  $('mission-state').textContent = `mission ${mission.id}: ${mission.state}`;
  $('upload-progress').hidden = false;
  $('upload-bar').max = Math.max(total, 1);
  $('upload-bar').value = acked;
  $('upload-text').textContent = `${acked} of ${total} waypoints acknowledged (${sent} sent)`;
  const list = $('upload-items');
  if (list.children.length !== total) {
    list.replaceChildren(...Array.from({ length: total }, (_, i) => {
      const li = document.createElement('li');
      li.textContent = String(i);
      return li;
    }));
  }
  [...list.children].forEach((li, i) => {
    const status = i < acked ? 'acked' : i < sent ? 'sent' : 'waiting';
    li.className = status;
    li.title = `waypoint ${i}: ${status}`;
  });
  if (mission.state === 'failed' && mission.error) showError('upload', new Error(mission.error));
}

async function upload() {
  showError('upload', null);
  const button = $('upload');
  button.disabled = true;
  try {
    let mission = await api.post('/api/missions', { plan_id: state.plan.id });
    renderMission(mission);
    while (mission.state === 'uploading') {
      await sleep(200);
      mission = await api.get(`/api/missions/${mission.id}`);
      if (!state.mission || state.mission.id === mission.id) renderMission(mission);
    }
  } catch (err) {
    showError('upload', err);
  } finally {
    updateStale();
  }
}

async function command(name) {
  showError('command', null);
  $('command-result').textContent = '';
  const buttons = document.querySelectorAll('[data-command]');
  buttons.forEach((b) => { b.disabled = true; });
  try {
    const r = await api.post('/api/boat/command', { command: name });
    $('command-result').textContent = `${name.toUpperCase()}: ${r.result}, boat ${r.state ?? '–'}`;
    if (name === 'start') {
      state.follow = true;
      $('follow').checked = true;
    }
  } catch (err) {
    showError('command', err);
  } finally {
    buttons.forEach((b) => { b.disabled = false; });
  }
}

// --- link status -----------------------------------------------------------------------------

function setPill(el, text, kind) {
  el.textContent = text;
  el.className = `pill pill-${kind}`;
}

async function pollBoat() {
  try {
    const boat = await api.get('/api/boat');
    const link = boat.link;
    setPill($('link-state'), link.up ? `link up${link.simulated ? ' (simulated boat)' : ''}`
      : `link down${link.error ? `: ${link.error}` : ''}`, link.up ? 'ok' : 'bad');
    $('hb-age').textContent = fmt(link.heartbeat_age_s);
    $('tm-age').textContent = fmt(link.telemetry_age_s);
    $('frames').textContent = String(link.frames ?? '–');
    $('frames-lost').textContent = link.frames_lost == null ? '–' : String(link.frames_lost);
    if (boat.boat) $('boat-state').textContent = `${boat.boat.state} (${boat.boat.mode})`;
  } catch (err) {
    setPill($('link-state'), `station unreachable`, 'bad');
  }
}

function addMessage(item) {
  const li = document.createElement('li');
  li.className = `sev-${String(item.severity).toLowerCase()}`;
  li.textContent = `${new Date(item.time).toLocaleTimeString()} ${item.severity}: ${item.text}`;
  const list = $('messages');
  list.prepend(li);
  while (list.children.length > 20) list.lastChild.remove();
}

// --- live websocket ---------------------------------------------------------------------------

function connectLive(delay = 500) {
  const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws/live`;
  const ws = new WebSocket(url);
  ws.onopen = () => setPill($('live-state'), 'live: connected', 'ok');
  ws.onmessage = (ev) => {
    const msg = JSON.parse(ev.data);
    handleLive(msg.type, msg.data);
  };
  ws.onclose = () => {
    const next = Math.min(delay * 2, 5000);
    setPill($('live-state'), `live: reconnecting in ${(next / 1000).toFixed(1)} s`, 'bad');
    setTimeout(() => connectLive(next), next);
  };
}

function handleLive(type, data) {
  switch (type) {
    case 'hello':
      if (data.telemetry) onTelemetry(data.telemetry, false);
      if (data.run != null && (!state.shown || state.shown.id !== data.run)) {
        showRun(data.run, { live: true });
      }
      (data.status ?? []).forEach(addMessage);
      break;
    case 'telemetry':
      onTelemetry(data, true);
      break;
    case 'mission':
      if (!state.mission || state.mission.id === data.id || data.state === 'uploading') {
        renderMission(data);
      }
      break;
    case 'run':
      refreshRuns();
      if (data.state === 'active' && state.follow) {
        if (!state.shown || state.shown.id !== data.id) showRun(data.id, { live: true });
      } else if (state.shown && state.shown.id === data.id) {
        state.shown.live = false;
      }
      break;
    case 'link':
      setPill($('link-state'), data.up ? 'link up' : `link down: ${data.reason ?? ''}`,
        data.up ? 'ok' : 'bad');
      break;
    case 'status':
      addMessage(data);
      break;
    case 'scenario':
      editor.reloadIfClean();
      break;
    default:
      break;
  }
}

// --- time bar ---------------------------------------------------------------------------------

function togglePlay() {
  const button = $('play');
  if (state.playing) {
    clearInterval(state.playing);
    state.playing = null;
    button.textContent = 'Play';
    button.setAttribute('aria-pressed', 'false');
    return;
  }
  state.follow = false;
  $('follow').checked = false;
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

// --- start-up ---------------------------------------------------------------------------------

async function linkViser() {
  const link = $('viser-link');
  try {
    const health = await api.get('/api/health');
    if (health.viser_port) {
      link.href = '/3d/'; // viser, served by the station behind the same token
      link.removeAttribute('aria-disabled');
      link.title = '3D view (viser) at /3d/';
    } else {
      link.textContent = '3D view: not running';
    }
  } catch {
    link.textContent = '3D view: unknown';
  }
}

async function restore() {
  try {
    const [plans, missions] = await Promise.all([api.get('/api/plans'), api.get('/api/missions')]);
    const done = plans.filter((p) => p.status === 'done')
      .sort((a, b) => a.created_at.localeCompare(b.created_at));
    if (done.length && !state.plan) showPlan(await api.get(`/api/plans/${done[done.length - 1].id}`));
    const latest = [...missions].sort((a, b) => a.created_at.localeCompare(b.created_at)).pop();
    if (latest && !state.mission) renderMission(latest);
  } catch (err) {
    showError('plan', err);
  }
  refreshRuns();
}

function bindControls() {
  $('plan').addEventListener('click', runPlan);
  $('upload').addEventListener('click', upload);
  for (const b of document.querySelectorAll('[data-command]')) {
    if (b.dataset.command === 'abort') continue;
    b.addEventListener('click', () => command(b.dataset.command));
  }
  const dialog = $('abort-dialog');
  $('cmd-abort').addEventListener('click', () => {
    dialog.returnValue = '';
    dialog.showModal();
  });
  dialog.addEventListener('close', () => {
    if (dialog.returnValue === 'abort') command('abort');
  });
  $('time').addEventListener('input', (e) => {
    state.follow = false;
    $('follow').checked = false;
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
  $('tile-url').value = localStorage.getItem('usv-station-tile-url') ?? '';
  $('tile-form').addEventListener('submit', (e) => {
    e.preventDefault();
    const url = $('tile-url').value.trim();
    localStorage.setItem('usv-station-tile-url', url);
    map.setTileUrl(url);
    $('settings-status').textContent = url ? `online map: ${url}` : 'offline grid only';
  });
  $('token-form').addEventListener('submit', (e) => {
    e.preventDefault();
    api.setToken($('token').value);
    $('token').value = '';
    $('settings-status').textContent = 'token saved for this browser tab';
  });
}

/** Let the browser paint and handle input between the start-up steps (no long tasks). */
const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });

async function main() {
  api.adoptTokenFromUrl();
  await nextTask();
  map = new ConsoleMap($('map'), {
    onClick: (x, y) => editor.mapClicked(x, y),
    onStartMoved: (x, y) => editor.moveStart(x, y),
    onObstacleMoved: (i, x, y) => editor.moveObstacle(i, x, y),
  });
  await nextTask();
  charts = new TelemetryCharts($('chart-heading'), $('chart-speed'));
  await nextTask();
  editor = new ScenarioEditor({
    map,
    centre: () => map.centreRamp(),
    onChange: () => updateStale(),
  });
  const tileUrl = localStorage.getItem('usv-station-tile-url');
  if (tileUrl) map.setTileUrl(tileUrl);
  bindControls();
  connectLive();
  await editor.load({ fit: true });
  pollBoat();
  setInterval(pollBoat, BOAT_POLL_MS);
  linkViser();
  restore();
}

// for tests and the curious: the map and a few counters
window.usvConsole = {
  get map() { return map; },
  get state() { return state; },
  planPositionAt,
};

main();
