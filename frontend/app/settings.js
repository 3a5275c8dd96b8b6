// Settings kept per browser (localStorage): the palette (day, dusk, night), large text,
// speed units, warning sound, the online tile URL and the offline chart; the access token
// (per tab) is api.js's. Keyboard shortcuts are listed on `?`.

import * as api from './api.js';
import { emit, ui } from './store.js';
import { $ } from './util.js';

const KEY = 'usv-station-settings';
const TILE_KEY = 'usv-station-tile-url';
const KNOT_MS = 1852 / 3600;
export const PALETTES = ['day', 'dusk', 'night'];
const DEFAULTS = { palette: 'day', large: false, units: 'ms', sound: true, chart: '' };

function load() {
  try {
    const stored = JSON.parse(localStorage.getItem(KEY) ?? '{}');
    if (!stored.palette && stored.night) stored.palette = 'night'; // the earlier night box
    delete stored.night;
    return { ...DEFAULTS, ...stored };
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
  const { palette, large, units, sound, chart } = settings;
  localStorage.setItem(KEY, JSON.stringify({ palette, large, units, sound, chart }));
}

/** The next palette: day, dusk, night, day... (the `n` shortcut). */
export function nextPalette() {
  return PALETTES[(PALETTES.indexOf(settings.palette) + 1) % PALETTES.length];
}

export function setSetting(name, value) {
  settings[name] = value;
  save();
  apply();
}

/** The page as the settings say: palette, text size, unit labels, the form's state. */
function apply() {
  const root = document.documentElement;
  if (!PALETTES.includes(settings.palette)) settings.palette = 'day';
  for (const name of PALETTES) root.classList.toggle(name, name !== 'day' && settings.palette === name);
  root.classList.toggle('large', settings.large);
  $('set-palette').value = settings.palette;
  $('set-large').checked = settings.large;
  $('set-units').value = settings.units;
  $('alert-sound').checked = settings.sound;
  document.querySelectorAll('.speed-unit').forEach((el) => { el.textContent = settings.unitLabel; });
  emit('units', settings.units);
  emit('palette', settings.palette);
}

export function applyStoredTiles() {
  const tileUrl = localStorage.getItem(TILE_KEY);
  if (tileUrl) ui.map.setTileUrl(tileUrl);
}

export function bindSettings() {
  apply();
  $('set-palette').addEventListener('change', (e) => setSetting('palette', e.target.value));
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
