// A small JSON-schema checker for the subset topay-viz's channel schemas use (docs/viewer.md,
// procs/viz/viz_channels.cc): "type" (a name or a list of names: object, array, number, integer,
// string, boolean, null), "properties", "additionalProperties" (false: no other keys), "items",
// "minItems" / "maxItems", "required", and "contentEncoding": "base64" on strings. Anything else in
// a schema is reported as unsupported rather than silently ignored.
//
// validate(schema, value) -> list of problems ("" path = the root), empty when the value conforms.

import { pathToFileURL } from 'node:url';

const KNOWN = new Set(['type', 'properties', 'additionalProperties', 'items', 'minItems', 'maxItems', 'required',
  'contentEncoding', 'description', 'title', '$schema']);
const BASE64 = /^(?:[A-Za-z0-9+/]{4})*(?:[A-Za-z0-9+/]{2}==|[A-Za-z0-9+/]{3}=)?$/;

function typeOf(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'array';
  return typeof value;  // object, number, string, boolean
}

function hasType(value, type) {
  switch (type) {
    case 'integer': return typeof value === 'number' && Number.isInteger(value);
    case 'number': return typeof value === 'number' && Number.isFinite(value);
    default: return typeOf(value) === type;
  }
}

export function validate(schema, value, path = '', problems = []) {
  if (typeof schema !== 'object' || schema === null) {
    problems.push(`${path}: schema is not an object`);
    return problems;
  }
  for (const key of Object.keys(schema)) {
    if (!KNOWN.has(key)) problems.push(`${path}: unsupported schema keyword "${key}"`);
  }
  if (schema.type !== undefined) {
    const types = Array.isArray(schema.type) ? schema.type : [schema.type];
    if (!types.some((t) => hasType(value, t))) {
      problems.push(`${path}: ${JSON.stringify(value)?.slice(0, 60)} is ${typeOf(value)}, not ${types.join(' | ')}`);
      return problems;
    }
  }
  if (typeOf(value) === 'object') {
    const properties = schema.properties || {};
    for (const [key, sub] of Object.entries(properties)) {
      if (key in value) validate(sub, value[key], `${path}.${key}`, problems);
    }
    for (const key of schema.required || []) {
      if (!(key in value)) problems.push(`${path}: missing required "${key}"`);
    }
    if (schema.additionalProperties === false) {
      for (const key of Object.keys(value)) if (!(key in properties)) problems.push(`${path}: unexpected "${key}"`);
    }
  }
  if (Array.isArray(value)) {
    if (schema.minItems !== undefined && value.length < schema.minItems) {
      problems.push(`${path}: ${value.length} items < minItems ${schema.minItems}`);
    }
    if (schema.maxItems !== undefined && value.length > schema.maxItems) {
      problems.push(`${path}: ${value.length} items > maxItems ${schema.maxItems}`);
    }
    if (schema.items) value.forEach((item, i) => validate(schema.items, item, `${path}[${i}]`, problems));
  }
  if (typeof value === 'string' && schema.contentEncoding === 'base64' && !BASE64.test(value)) {
    problems.push(`${path}: not base64`);
  }
  return problems;
}

/** The properties a schema names at every object level that the value lacks (docs/viewer.md lists them all). */
export function missingProperties(schema, value, path = '', missing = []) {
  if (typeOf(value) === 'object' && schema.properties) {
    for (const [key, sub] of Object.entries(schema.properties)) {
      if (!(key in value)) missing.push(`${path}.${key}`);
      else missingProperties(sub, value[key], `${path}.${key}`, missing);
    }
  } else if (Array.isArray(value) && schema.items) {
    value.forEach((item, i) => missingProperties(schema.items, item, `${path}[${i}]`, missing));
  }
  return missing;
}

// Self-check of the checker (node tests/web/json_schema.mjs): every rule rejects what it should.
if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  const { deepEqual } = await import('node:assert/strict');
  const schema = {
    type: 'object', additionalProperties: false, required: ['n'],
    properties: {
      n: { type: 'integer' }, x: { type: ['number', 'null'] }, s: { type: 'string', contentEncoding: 'base64' },
      v: { type: 'array', items: { type: 'number' }, minItems: 3, maxItems: 3 }, b: { type: 'boolean' },
      o: { type: 'object', properties: { a: { type: 'array', items: { type: 'array', items: { type: 'number' } } } } },
    },
  };
  deepEqual(validate(schema, { n: 1, x: null, s: 'AAE=', v: [1, 2, 3], b: true, o: { a: [[1], []] } }), []);
  deepEqual(validate(schema, { n: 1.5 }).length, 1);
  deepEqual(validate(schema, { n: 1, x: 'a' }).length, 1);
  deepEqual(validate(schema, { n: 1, s: 'A!==' }).length, 1);
  deepEqual(validate(schema, { n: 1, v: [1, 2] }).length, 1);
  deepEqual(validate(schema, { n: 1, v: [1, 2, 3, 4] }).length, 1);
  deepEqual(validate(schema, { n: 1, v: [1, '2', 3] }).length, 1);
  deepEqual(validate(schema, { n: 1, b: 0 }).length, 1);
  deepEqual(validate(schema, { n: 1, o: { a: [[1, null]] } }).length, 1);
  deepEqual(validate(schema, { n: 1, z: 1 }).length, 1);
  deepEqual(validate(schema, {}).length, 1);
  deepEqual(validate(schema, []).length, 1);
  deepEqual(validate({ type: 'object', pattern: 'x' }, {}).length, 1);
  deepEqual(missingProperties(schema, { n: 1, o: {} }), ['.x', '.s', '.v', '.b', '.o.a']);
  console.log('json_schema.mjs: self-check passed');
}
