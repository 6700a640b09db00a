// Small text formatters shared by the panels.

/** A number with `digits` decimals, or "—" when missing / not finite. */
export function num(value, digits = 2) {
  return typeof value === 'number' && Number.isFinite(value) ? value.toFixed(digits) : '—';
}

/** Seconds since the epoch -> local "HH:MM:SS.s". */
export function clock(t) {
  if (typeof t !== 'number' || !Number.isFinite(t)) return '—';
  const d = new Date(t * 1000);
  const pad = (n) => String(n).padStart(2, '0');
  return `${pad(d.getHours())}:${pad(d.getMinutes())}:${pad(d.getSeconds())}.${Math.floor((t * 10) % 10)}`;
}

/** Bytes -> "12.3 kB" style. */
export function bytes(n) {
  if (typeof n !== 'number' || !Number.isFinite(n)) return '—';
  if (n < 1024) return `${n.toFixed(0)} B`;
  if (n < 1024 * 1024) return `${(n / 1024).toFixed(1)} kB`;
  if (n < 1024 * 1024 * 1024) return `${(n / 1024 / 1024).toFixed(1)} MB`;
  return `${(n / 1024 / 1024 / 1024).toFixed(2)} GB`;
}

/** A value of any JSON type as short text. */
export function any(value) {
  if (value === null || value === undefined) return '—';
  if (typeof value === 'number') return Number.isInteger(value) ? String(value) : value.toFixed(3);
  if (typeof value === 'boolean') return value ? 'yes' : 'no';
  if (Array.isArray(value)) return value.map(any).join(', ');
  if (typeof value === 'object') return JSON.stringify(value);
  return String(value);
}
