// The boat card: the boat's latest reported state.

import { on } from './store.js';
import { $, fmt } from './util.js';

export function bindInstruments() {
  on('boat-drawn', (row) => {
    $('boat-x').textContent = fmt(row.x);
    $('boat-y').textContent = fmt(row.y);
    $('boat-heading').textContent = fmt(row.ramp_heading_deg, 0);
    $('boat-compass').textContent = fmt(row.heading_deg, 0);
    $('boat-speed').textContent = fmt(row.speed, 2);
    $('boat-state').textContent = row.mode ?? '–';
  });
}
