// The working scenario editor: start, current and obstacles, from the form or the
// map. Every change is saved to the station (PUT /api/scenario, with the token)
// shortly after the last keystroke; the station's refusal shows next to the form.

import * as api from './api.js';

const SAVE_DELAY_MS = 500;
const NEW_OBSTACLE_RADIUS_M = 2;
const OBSTACLE_COLUMNS = [
  ['x', 'x (m)', '0.1'],
  ['y', 'y (m)', '0.1'],
  ['radius', 'radius (m)', '0.1'],
  ['vx', 'vx (m/s)', '0.1'],
  ['vy', 'vy (m/s)', '0.1'],
];

const $ = (id) => document.getElementById(id);
const round1 = (v) => Math.round(v * 10) / 10;
const canonical = (s) => JSON.stringify(s);

function getPath(obj, path) {
  return path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), obj);
}

function setPath(obj, path, value) {
  const keys = path.split('.');
  const last = keys.pop();
  const target = keys.reduce((o, k) => o[k], obj);
  target[last] = value;
}

/** The station names obstacles by list index (`obstacles[0]`); the table numbers them from 1. */
export function obstaclesFromOne(message) {
  return String(message).replace(/obstacles\[(\d+)\]/g, (_, i) => `obstacle ${Number(i) + 1}`);
}

export class ScenarioEditor {
  constructor({ map, centre, onChange }) {
    this.map = map;
    this.centre = centre;
    this.onChange = onChange;
    this.scenario = null;
    this.version = 0;
    this.savedVersion = 0;
    this.timer = null;
    this.inflight = Promise.resolve();
    this.lastError = null;
    this.invalid = new Set();
    for (const input of document.querySelectorAll('input[data-field]')) {
      input.addEventListener('input', () => this.fieldEdited(input));
    }
    $('add-obstacle').addEventListener('click', () => {
      const [x, y] = this.centre();
      this.addObstacle(x, y);
    });
  }

  get dirty() {
    return this.version !== this.savedVersion || this.timer !== null;
  }

  async load({ fit = false } = {}) {
    try {
      this.scenario = await api.get('/api/scenario');
    } catch (err) {
      $('scenario-error').textContent = `cannot read the working scenario: ${err.message}`;
      return;
    }
    this.version = 0;
    this.savedVersion = 0;
    this.invalid.clear();
    $('scenario-error').textContent = '';
    $('scenario-name').textContent = this.scenario.name;
    if (!this.scenario.origin) {
      $('scenario-status').textContent = 'This scenario has no origin: the map shows the ramp '
        + 'frame only, and a plan cannot be uploaded.';
    }
    this.map.setOrigin(this.scenario.origin);
    this.redraw();
    this.fillForm();
    if (fit) this.map.fitScenario(this.scenario);
    this.onChange();
  }

  reloadIfClean() {
    if (!this.dirty && this.invalid.size === 0) this.load();
  }

  /** True when `other` (a plan's scenario) is the scenario as edited here. */
  matches(other) {
    return Boolean(this.scenario) && canonical(other) === canonical(this.scenario);
  }

  fillForm() {
    for (const input of document.querySelectorAll('input[data-field]')) {
      input.value = String(getPath(this.scenario, input.dataset.field));
      input.removeAttribute('aria-invalid');
    }
    const rows = this.scenario.obstacles.map((o, i) => this.obstacleRow(o, i));
    $('obstacle-rows').replaceChildren(...rows);
  }

  obstacleRow(o, i) {
    const tr = document.createElement('tr');
    const th = document.createElement('th');
    th.scope = 'row';
    th.textContent = String(i + 1);
    tr.append(th);
    for (const [key, label, step] of OBSTACLE_COLUMNS) {
      const td = document.createElement('td');
      const input = document.createElement('input');
      input.type = 'number';
      input.step = step;
      if (key === 'radius') input.min = '0';
      input.value = String(o[key]);
      input.dataset.obstacle = String(i);
      input.dataset.key = key;
      input.setAttribute('aria-label', `obstacle ${i + 1} ${label}`);
      input.addEventListener('input', () => this.obstacleEdited(input));
      td.append(input);
      tr.append(td);
    }
    const td = document.createElement('td');
    const del = document.createElement('button');
    del.type = 'button';
    del.className = 'icon';
    del.textContent = '✕';
    del.title = `delete obstacle ${i + 1}`;
    del.setAttribute('aria-label', `delete obstacle ${i + 1}`);
    del.addEventListener('click', () => this.deleteObstacle(i));
    td.append(del);
    tr.append(td);
    return tr;
  }

  readNumber(input, label) {
    const v = input.valueAsNumber;
    // "8e" or "1e" typed on the way to a number: Chromium reports an empty value, and the
    // save planned for the "8" before it must not go out
    if (input.value.trim() === '' || !Number.isFinite(v) || input.validity.badInput) {
      input.setAttribute('aria-invalid', 'true');
      this.invalid.add(input);
      clearTimeout(this.timer);
      this.timer = null;
      $('scenario-error').textContent = `${label}: enter a number`;
      $('scenario-status').textContent = 'not saved';
      this.onChange();
      return null;
    }
    input.removeAttribute('aria-invalid');
    this.invalid.delete(input);
    return v;
  }

  fieldEdited(input) {
    const v = this.readNumber(input, input.dataset.field);
    if (v === null) return;
    setPath(this.scenario, input.dataset.field, v);
    this.changed({ redrawOnly: true });
  }

  obstacleEdited(input) {
    const i = Number(input.dataset.obstacle);
    const v = this.readNumber(input, input.getAttribute('aria-label'));
    if (v === null) return;
    this.scenario.obstacles[i][input.dataset.key] = v;
    this.changed({ redrawOnly: true });
  }

  mapClicked(x, y) {
    const mode = document.querySelector('input[name="click-mode"]:checked')?.value;
    if (mode === 'start') this.moveStart(x, y);
    else if (mode === 'obstacle') this.addObstacle(x, y);
  }

  moveStart(x, y) {
    this.scenario.start.x = round1(x);
    this.scenario.start.y = round1(y);
    this.changed();
  }

  moveObstacle(i, x, y) {
    this.scenario.obstacles[i].x = round1(x);
    this.scenario.obstacles[i].y = round1(y);
    this.changed();
  }

  addObstacle(x, y) {
    this.scenario.obstacles.push({ x: round1(x), y: round1(y), radius: NEW_OBSTACLE_RADIUS_M,
      vx: 0, vy: 0 });
    this.changed();
    const rows = $('obstacle-rows').children;
    rows[rows.length - 1]?.querySelector('input')?.focus({ preventScroll: true });
  }

  deleteObstacle(i) {
    this.scenario.obstacles.splice(i, 1);
    this.changed();
    const rows = $('obstacle-rows').children;
    (rows[Math.min(i, rows.length - 1)]?.querySelector('button') ?? $('add-obstacle')).focus();
  }

  redraw() {
    this.map.setScenario(this.scenario);
  }

  /** A change from the form (redrawOnly: keep the form as typed) or from the map. */
  changed({ redrawOnly = false } = {}) {
    this.version += 1;
    this.redraw();
    if (!redrawOnly) this.fillForm();
    this.onChange();
    if (this.invalid.size) return;
    clearTimeout(this.timer);
    this.timer = setTimeout(() => {
      this.timer = null;
      this.save();
    }, SAVE_DELAY_MS);
  }

  save() {
    this.inflight = this.inflight.then(async () => {
      if (this.invalid.size) return;
      const version = this.version;
      $('scenario-status').textContent = 'saving…';
      try {
        await api.put('/api/scenario', this.scenario);
        this.savedVersion = version;
        this.lastError = null;
        if (!this.invalid.size) $('scenario-error').textContent = '';
        $('scenario-status').textContent = `saved at ${new Date().toLocaleTimeString()}`;
      } catch (err) {
        this.lastError = err;
        $('scenario-error').textContent = obstaclesFromOne(err.message);
        $('scenario-status').textContent = 'not saved';
      }
    });
    return this.inflight;
  }

  /** Save now if a change is waiting; throws when the station refused the scenario. */
  async flush() {
    if (this.invalid.size) {
      throw new Error('the scenario has fields that are not numbers: fix them first');
    }
    if (this.timer !== null) {
      clearTimeout(this.timer);
      this.timer = null;
      this.save();
    }
    await this.inflight;
    if (this.lastError) throw new Error(`the scenario is not saved: ${this.lastError.message}`);
  }
}
