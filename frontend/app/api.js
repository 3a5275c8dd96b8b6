// The station's HTTP API: JSON requests with the station's cookie or a typed bearer token,
// and errors turned into one readable line for the control that caused them.

const TOKEN_KEY = 'usv-station-token';

/** Move ?token= from the address bar into session storage (kept for this tab only). */
export function adoptTokenFromUrl() {
  const url = new URL(window.location.href);
  const token = url.searchParams.get('token');
  if (token === null) return;
  sessionStorage.setItem(TOKEN_KEY, token);
  url.searchParams.delete('token');
  window.history.replaceState(null, '', url.pathname + url.search + url.hash);
}

export function getToken() {
  return sessionStorage.getItem(TOKEN_KEY) ?? '';
}

/** Keep a typed token for this tab and trade it for the station's HttpOnly cookie, which the
 * websocket, downloads and the 3D view need (they cannot send an Authorization header). */
export async function setToken(token) {
  sessionStorage.setItem(TOKEN_KEY, token.trim());
  try {
    await fetch(`/?token=${encodeURIComponent(token.trim())}`, { redirect: 'manual', cache: 'no-store' });
  } catch {
    // the header still carries the token for API requests
  }
}

export class ApiError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

/** One line from a FastAPI error body: `{detail: "..."}` or 422 `{detail: [{loc, msg}]}`. */
export function describeError(status, body, text) {
  const detail = body && body.detail;
  let message;
  if (Array.isArray(detail)) {
    message = detail
      .map((d) => {
        const loc = (d.loc || []).filter((p) => p !== 'body');
        const msg = String(d.msg || '').replace(/^Value error, /, '');
        return loc.length && !msg.startsWith(`${loc.join('.')}:`) ? `${loc.join('.')}: ${msg}` : msg;
      })
      .join('; ');
  } else if (typeof detail === 'string') {
    message = detail;
  } else {
    message = (text || '').trim().slice(0, 300) || `the station answered HTTP ${status}`;
  }
  if (status === 401) {
    message += ' (open the console with the link that usv-station serve prints, which carries '
      + '?token=…, or enter the token under Settings)';
  }
  return message;
}

export async function api(method, path, body) {
  const headers = { Accept: 'application/json' };
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  const token = getToken(); // else the station's cookie (set from the printed console URL)
  if (token) headers.Authorization = `Bearer ${token}`;
  let response;
  try {
    response = await fetch(path, {
      method,
      headers,
      body: body === undefined ? undefined : JSON.stringify(body),
      cache: 'no-store',
    });
  } catch (err) {
    throw new ApiError(0, `the station is unreachable (${err.message})`);
  }
  const text = await response.text();
  let data = null;
  try {
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) throw new ApiError(response.status, describeError(response.status, data, text));
  return data;
}

export const get = (path) => api('GET', path);
export const post = (path, body) => api('POST', path, body ?? {});
export const put = (path, body) => api('PUT', path, body);
