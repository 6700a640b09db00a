// Base64 strings of little-endian numbers (docs/viewer.md: "Binary arrays inside JSON") to typed
// arrays. The typed arrays view the decoded bytes directly on little-endian hosts (all current
// browsers); a big-endian host gets a byte-swapped copy.

const LITTLE_ENDIAN = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

/** Decodes a base64 string into bytes ("" -> empty). */
export function base64ToBytes(text) {
  if (!text) return new Uint8Array(0);
  if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(text);
  const binary = atob(text);
  const n = binary.length;
  const bytes = new Uint8Array(n);
  for (let i = 0; i < n; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

function decode16(text, ArrayType, getter) {
  const bytes = base64ToBytes(text);
  const n = bytes.length >> 1;
  if (LITTLE_ENDIAN && bytes.byteOffset % 2 === 0) return new ArrayType(bytes.buffer, bytes.byteOffset, n);
  const out = new ArrayType(n);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let i = 0; i < n; i++) out[i] = view[getter](2 * i, true);
  return out;
}

/** base64 of uint16 LE -> Uint16Array. */
export function base64ToUint16(text) {
  return decode16(text, Uint16Array, 'getUint16');
}

/** base64 of int16 LE -> Int16Array. */
export function base64ToInt16(text) {
  return decode16(text, Int16Array, 'getInt16');
}
