// The plan card: ask the station for a plan, show its metrics and path, and say
// when the scenario has changed since the plan was made.

import * as api from './api.js';
import { scheduleCharts, setDisplayTime } from './render.js';
import { obstaclesFromOne } from './scenario.js';
import { updateTimeRange } from './timebar.js';
import { speedIn } from './settings.js';
import { on, state, ui } from './store.js';
import { $, fmt, showError, sleep } from './util.js';

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

export function showPlan(job) {
  state.plan = job;
  const { map, charts, editor } = ui;
  const plan = job.plan;
  map.setPlan(plan, job.scenario.vessel);
  charts.setPlan(plan);
  scheduleCharts();
  map.setHorizon(plan.metrics.duration_s * 1.2);
  map.setScenario(editor.scenario);
  updateTimeRange();
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
  showSpeedLegend();
  $('speed-legend').hidden = false;
  updateStale();
  setDisplayTime(state.displayT);
}

function showSpeedLegend() {
  const [vmin, vmax] = ui.map.speedRange ?? [null, null];
  $('speed-min').textContent = fmt(speedIn(vmin), 1);
  $('speed-max').textContent = fmt(speedIn(vmax), 1);
}

/** The seed an empty seed box stands for: the scenario's planner.seed, else the planner's 1. */
export function updateSeedHint() {
  const seed = ui.editor.scenario?.planner?.seed ?? 1;
  const box = $('seed');
  box.placeholder = `${seed} (default)`;
  box.title = `empty: seed ${seed}, the same plan every time; enter another seed for another plan`;
}

export function updateStale() {
  updateSeedHint();
  // a plan from the boat is made from the working scenario it was asked against (its
  // `basis`), which is what must not have changed
  const basis = state.plan?.basisScenario ?? state.plan?.scenario;
  const stale = Boolean(state.plan) && !ui.editor.matches(basis);
  $('plan-stale').hidden = !stale;
  $('upload').disabled = !state.plan || stale;
}

/** Plan the working scenario, or (`fromBoat`) from where the boat is now: its position,
 * heading and speed, the obstacles where they are at that instant of the run. */
export async function runPlan({ fromBoat = false } = {}) {
  showError('plan', null);
  const button = $(fromBoat ? 'plan-from-boat' : 'plan');
  button.disabled = true;
  const started = performance.now();
  const progress = $('plan-progress');
  try {
    await ui.editor.flush();
    const seedText = $('seed').value.trim();
    const body = seedText === '' ? {} : { seed: Number(seedText) };
    if (fromBoat) body.from_boat = true;
    const asked = JSON.parse(JSON.stringify(ui.editor.scenario));
    if (!$('planner-label').hidden && $('planner').value) body.planner = $('planner').value;
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
    if (fromBoat) job.basisScenario = asked;
    showPlan(job);
    refreshOverlayChoices();
  } catch (err) {
    showError('plan', new Error(obstaclesFromOne(err.message ?? err)));
  } finally {
    state.waitingPlan = null;
    progress.hidden = true;
    button.disabled = false;
  }
}

/** The planners the station offers (GET /api/planners); no select when it has none. */
async function loadPlanners() {
  let planners;
  try {
    planners = await api.get('/api/planners');
  } catch (err) {
    if (err.status !== 404) showError('plan', err);
    return;
  }
  const select = $('planner');
  select.replaceChildren(...planners.map((p) => {
    const opt = document.createElement('option');
    opt.value = p.name;
    opt.textContent = p.title ? `${p.name}: ${p.title}` : p.name;
    opt.title = [p.paper, (p.capabilities ?? []).join(', ')].filter(Boolean).join('; ');
    return opt;
  }));
  $('planner-label').hidden = planners.length === 0;
}

/** The finished plans, newest first, to overlay on the shown one. */
export async function refreshOverlayChoices() {
  let plans;
  try {
    plans = await api.get('/api/plans');
  } catch {
    return;
  }
  const select = $('overlay-plan');
  const keep = select.value;
  const done = plans.filter((p) => p.status === 'done')
    .sort((a, b) => b.created_at.localeCompare(a.created_at));
  select.replaceChildren(select.options[0], ...done.map((p) => {
    const opt = document.createElement('option');
    opt.value = p.id;
    const at = new Date(p.created_at).toLocaleTimeString([], { hour12: false });
    opt.textContent = `${at} ${p.planner} seed ${p.seed ?? '–'} (${p.scenario}), `
      + `fitness ${Number(p.fitness).toFixed(3)}`;
    return opt;
  }));
  if (done.some((p) => p.id === keep)) select.value = keep;
}

async function overlay(id) {
  $('overlay-metrics').textContent = '';
  if (!id) {
    ui.map.setOverlayPlan(null);
    return;
  }
  try {
    const job = await api.get(`/api/plans/${id}`);
    ui.map.setOverlayPlan(job.plan);
    const m = job.plan.metrics;
    $('overlay-metrics').textContent = `overlay (dashed): ${job.plan.planner}, length `
      + `${fmt(m.length_m)} m, duration ${fmt(m.duration_s)} s, min. clearance `
      + `${fmt(m.min_clearance_m, 2)} m, fitness ${fmt(m.fitness, 4)}`;
  } catch (err) {
    showError('plan', err);
  }
}

export function bindPlanControls() {
  $('plan').addEventListener('click', () => runPlan());
  $('plan-from-boat').addEventListener('click', () => runPlan({ fromBoat: true }));
  on('units', showSpeedLegend);
  $('overlay-plan').addEventListener('change', (e) => overlay(e.target.value));
  $('overlay-plan').addEventListener('focus', refreshOverlayChoices);
  loadPlanners();
  refreshOverlayChoices();
}
