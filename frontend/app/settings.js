// Settings kept per browser (localStorage): night mode, large text, speed units,
// warning sound, the online tile URL and the offline chart; the access token
// (per tab) is api.js's. Keyboard shortcuts are listed on `?`.

import * as api from './api.js';
import { emit, ui } from './store.js';
import { $ } from './util.js';

const KEY = 'usv-station-settings';
const TILE_KEY = 'usv-station-tile-url';
const KNOT_MS = 1852 / 3600;
const DEFAULTS = { night: false, large: false, units: 'ms', sound: true, chart: '' };

function load() {
  try {
    return { ...DEFAULTS, ...JSON.parse(localStorage.getItem(KEY) ?? '{}') };
  } catch {
    return { ...DEFAULTS };
  }
}

export const settings = {
  ...load(),
  get unitLabel() { return this.units === 'kn' ? 'kn' : 'm/s'; },
};

/** A speed in m/s in the chosen unit. */
export function speedIn(ms) {
  if (ms == null) return ms;
  return settings.units === 'kn' ? ms / KNOT_MS : ms;
}

function save() {
  const { night, large, units, sound, chart } = settings;
  localStorage.setItem(KEY, JSON.stringify({ night, large, units, sound, chart }));
}

export function setSetting(name, value) {
  settings[name] = value;
  save();
  apply();
}

/** The page as the settings say: palette, text size, unit labels, the form's state. */
function apply() {
  const root = document.documentElement;
  root.classList.toggle('night', settings.night);
  root.classList.toggle('large', settings.large);
  $('set-night').checked = settings.night;
  $('set-large').checked = settings.large;
  $('set-units').value = settings.units;
  $('alert-sound').checked = settings.sound;
  document.querySelectorAll('.speed-unit').forEach((el) => { el.textContent = settings.unitLabel; });
  emit('units', settings.units);
  emit('palette', settings.night);
}

export function applyStoredTiles() {
  const tileUrl = localStorage.getItem(TILE_KEY);
  if (tileUrl) ui.map.setTileUrl(tileUrl);
}

export function bindSettings() {
  apply();
  $('set-night').addEventListener('change', (e) => setSetting('night', e.target.checked));
  $('set-large').addEventListener('change', (e) => setSetting('large', e.target.checked));
  $('set-units').addEventListener('change', (e) => setSetting('units', e.target.value));
  $('alert-sound').addEventListener('change', (e) => setSetting('sound', e.target.checked));
  $('tile-url').value = localStorage.getItem(TILE_KEY) ?? '';
  $('tile-form').addEventListener('submit', (e) => {
    e.preventDefault();
    const url = $('tile-url').value.trim();
    localStorage.setItem(TILE_KEY, url);
    ui.map.setTileUrl(url);
    $('settings-status').textContent = url ? `online map: ${url}` : 'offline grid only';
  });
  $('token-form').addEventListener('submit', (e) => {
    e.preventDefault();
    api.setToken($('token').value);
    $('token').value = '';
    $('settings-status').textContent = 'token saved for this browser tab';
  });
}
