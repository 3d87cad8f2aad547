#!/usr/bin/env node
// The Khronos glTF-Validator as an oracle for the loader: both read every file
// of a corpus (tests/validator/hostile), and
// - a file the validator finds an error in that can change what is drawn or
//   how memory is touched (MUST_REJECT below) must be rejected by the loader
//   ('shadelgraph inspect' exits 1 with one 'shadelgraph: error:' line), else
//   the test fails; the report says how many of those messages name the
//   object of the validator's JSON pointer ("accessor 3", "accessors[3]" or
//   "/accessors/3");
// - the loader must never crash or hang (any exit other than 0 or 1, or a
//   message that is not one line, fails);
// - everything else (cosmetic errors, files the validator finds valid that the
//   loader rejects) is counted in the agreement figure and listed by class.
//
// usage: differential.js --loader PATH/shadelgraph --corpus DIR [--report FILE.json] [--verbose]
//        [--hang-seconds N]  (a loader run longer than N s counts as a hang; 20)
// Exit: 0 pass, 1 fail, 77 skipped (the validator is not installed: ./sg deps).
'use strict';
const fs = require('fs');
const path = require('path');
const { execFile } = require('child_process');

const root = path.resolve(__dirname, '..', '..');
const validatorDir = path.join(root, 'tools', 'gltf-validator', 'node_modules', 'gltf-validator');

// Validator error codes whose files the loader must reject.
const MUST_REJECT = new Set([
  'UNRESOLVED_REFERENCE', 'ACCESSOR_TOO_LONG', 'ACCESSOR_INDEX_OOB', 'ACCESSOR_SPARSE_INDEX_OOB',
  'ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE', 'ACCESSOR_INVALID_FLOAT', 'BUFFER_VIEW_TOO_LONG', 'BUFFER_BYTE_LENGTH_MISMATCH',
  'BUFFER_MISSING_GLB_DATA', 'BUFFER_GLB_CHUNK_TOO_BIG', 'MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT',
  'MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT', 'MESH_PRIMITIVE_INDICES_ACCESSOR_INVALID_FORMAT',
  'MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE', 'NODE_LOOP', 'INVALID_JSON', 'INVALID_GLTF', 'INVALID_URI',
  'IO_ERROR', 'BUFFER_DATA_URI_MIME_TYPE_INVALID',
  'JSON_TOO_DEEP',  // ours: nesting the validator's own recursive parser dies of (see jsonDepth)
  'VALIDATOR_FAILED',  // the validator cannot read it at all (e.g. "could not detect glTF format")
]);
const MAX_VALIDATOR_DEPTH = 1000;

// The deepest nesting of [ and { in the bytes (outside strings): the
// validator's parser recurses and throws where it cannot be caught.
function jsonDepth(bytes) {
  let depth = 0, deepest = 0, inString = false;
  for (let i = 0; i < bytes.length; i++) {
    const c = bytes[i];
    if (inString) {
      if (c === 0x5c) i++;
      else if (c === 0x22) inString = false;
    } else if (c === 0x22) inString = true;
    else if (c === 0x5b || c === 0x7b) deepest = Math.max(deepest, ++depth);
    else if (c === 0x5d || c === 0x7d) depth--;
  }
  return deepest;
}
// Generic schema errors are must-reject where they hit a reference, a size
// or an offset (an index out of range, a count of 0 or 2^62, an unknown type).
const SCHEMA = new Set(['VALUE_NOT_IN_RANGE', 'TYPE_MISMATCH', 'INVALID_INDEX', 'UNDEFINED_PROPERTY',
                        'VALUE_NOT_IN_LIST', 'ARRAY_LENGTH_NOT_IN_LIST', 'INVALID_INTEGER']);
const REFERENCE_OR_SIZE = new Set(['scene', 'nodes', 'children', 'mesh', 'camera', 'skin', 'indices', 'material',
  'bufferView', 'buffer', 'source', 'sampler', 'index', 'count', 'byteOffset', 'byteLength', 'byteStride',
  'componentType', 'type', 'attributes', 'POSITION', 'mode', 'values']);

function mustReject(issue) {
  if (issue.code.startsWith('GLB_')) return true;
  // normalized: true on a FLOAT accessor (ACCESSOR_NORMALIZED_INVALID too): the
  // flag means nothing for floats and the loader reads them as they are.
  if (issue.code === 'MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT' && /FLOAT normalized\}/.test(issue.message))
    return false;
  if (MUST_REJECT.has(issue.code)) return true;
  if (!SCHEMA.has(issue.code)) return false;
  const keys = (issue.pointer || '').split('/').filter((k) => k !== '' && !/^\d+$/.test(k));
  return keys.length > 0 && REFERENCE_OR_SIZE.has(keys[keys.length - 1]);
}

// The object a JSON pointer lies in ("/meshes/0/primitives/1/indices" -> meshes, 0) and how the loader may name it.
const SINGULAR = { scenes: 'scene', nodes: 'node', meshes: 'mesh', accessors: 'accessor', bufferViews: 'bufferView',
  buffers: 'buffer', materials: 'material', textures: 'texture', images: 'image', samplers: 'sampler',
  cameras: 'camera', skins: 'skin', animations: 'animation', lights: 'light' };
function namesPointer(message, pointer) {
  const keys = (pointer || '').split('/').slice(1);
  if (keys.length === 0 || keys[0] === '') return true;  // the document itself (GLB, JSON syntax)
  let i = keys[0] === 'extensions' ? 2 : 0;  // /extensions/KHR_lights_punctual/lights/0
  if (keys.length < i + 2 || !/^\d+$/.test(keys[i + 1])) return message.includes(keys[i]);
  const [collection, index] = [keys[i], keys[i + 1]];
  const singular = SINGULAR[collection] || collection;
  const forms = [`${collection}[${index}]`, `/${collection}/${index}`, `${singular} ${index}`];
  return forms.some((form) => new RegExp(`(^|[^A-Za-z])${form.replace(/[[\]/]/g, '\\$&')}(?!\\d)`).test(message));
}

// A primitive the loader skips with a warning ("mesh 0 'x' primitive 1: unknown
// mode 7; skipped") is not drawn and its data not read: an error inside it is
// handled.
function skippedByLoader(issue, warnings) {
  const m = /^\/meshes\/(\d+)\/primitives\/(\d+)(\/|$)/.exec(issue.pointer || '');
  if (!m) return false;
  const primitive = new RegExp(`mesh ${m[1]}\\b.*primitive ${m[2]}: .*skipped`);
  return warnings.some((w) => primitive.test(w));
}

function runLoader(loader, file, hangSeconds) {
  return new Promise((resolve) => {
    execFile(loader, ['inspect', file], { timeout: hangSeconds * 1000, maxBuffer: 1 << 26 }, (error, stdout, stderr) => {
      const code = error ? (typeof error.code === 'number' ? error.code : null) : 0;
      const warnings = stdout.split('\n').filter((line) => line.startsWith('warning: '));
      resolve({ code, signal: error && error.signal, killed: error && error.killed, stderr: stderr.trim(), warnings });
    });
  });
}

async function pool(items, width, work) {
  const results = new Array(items.length);
  let next = 0;
  await Promise.all(Array.from({ length: width }, async () => {
    while (next < items.length) {
      const i = next++;
      results[i] = await work(items[i]);
    }
  }));
  return results;
}

function increment(map, key, field) {
  const entry = map.get(key) || { files: 0, rejected: 0, accepted: 0 };
  entry.files++;
  entry[field]++;
  map.set(key, entry);
}

async function main() {
  const args = process.argv.slice(2);
  const option = (name) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : undefined; };
  const loader = option('--loader'), corpus = option('--corpus'), reportPath = option('--report');
  const verbose = args.includes('--verbose');
  const hangSeconds = Number(option('--hang-seconds') || 20);
  if (!loader || !corpus) {
    console.error('usage: differential.js --loader PATH/shadelgraph --corpus DIR [--report FILE.json] [--verbose]');
    process.exit(2);
  }
  if (!fs.existsSync(validatorDir)) {
    console.log(`SKIPPED: the Khronos glTF-Validator is not installed at ${validatorDir} (./sg deps installs it)`);
    process.exit(77);
  }
  const validator = require(validatorDir);
  const files = fs.readdirSync(corpus).filter((f) => /\.(gltf|glb)$/.test(f)).sort();
  const width = Math.max(1, Math.min(2, require('os').cpus().length));

  const rows = await pool(files, width, async (name) => {
    const file = path.join(corpus, name);
    let issues, pointers = [];
    const bytes = fs.readFileSync(file);
    try {
      if (jsonDepth(bytes) > MAX_VALIDATOR_DEPTH)
        throw Object.assign(new Error('nested deeper than the validator handles'), { depthCode: 'JSON_TOO_DEEP' });
      const report = await validator.validateBytes(new Uint8Array(bytes), {
        uri: name, maxIssues: 0, externalResourceFunction: () => Promise.reject(new Error('no external files')),
      });
      issues = report.issues.messages.filter((m) => m.severity === 0);
      // Where the validator points with a warning counts for naming too (a bad
      // componentType is a warning on the accessor and an error on its mesh).
      pointers = report.issues.messages.filter((m) => m.severity <= 1).map((m) => m.pointer);
    } catch (e) {
      issues = [{ code: e.depthCode || 'VALIDATOR_FAILED', message: String(e), severity: 0 }];
    }
    return { name, issues, pointers, loader: await runLoader(loader, file, hangSeconds) };
  });

  let agree = 0, mustRejectFiles = 0, mustRejectNamed = 0;
  const failures = [], byCode = new Map(), validButRejected = new Map(), silent = new Map();
  for (const row of rows) {
    const l = row.loader;
    const lines = l.stderr.split('\n').filter((s) => s.startsWith('shadelgraph: error:'));
    if (l.code !== 0 && l.code !== 1) {
      failures.push(`${row.name}: the loader ${l.killed ? 'hung' : l.signal ? 'died of ' + l.signal : 'exited ' + l.code}`);
      continue;
    }
    const rejected = l.code === 1;
    if (rejected && lines.length !== 1)
      failures.push(`${row.name}: expected one 'shadelgraph: error:' line, got: ${l.stderr.slice(0, 300)}`);
    const message = lines.join(' ');
    const hostile = row.issues.filter((i) => mustReject(i) && !skippedByLoader(i, l.warnings));
    if ((row.issues.length > 0) === rejected) agree++;
    for (const code of new Set(row.issues.map((i) => i.code))) increment(byCode, code, rejected ? 'rejected' : 'accepted');
    if (row.issues.length === 0 && rejected) {
      const what = message.replace(/^shadelgraph: error: [^:]*: /, '').replace(/\d+/g, 'N').slice(0, 90);
      increment(validButRejected, what, 'rejected');
    }
    // Loaded despite errors outside the must-reject classes: fine with a warning
    // that names the place, counted (not failed) without one.
    if (!rejected && hostile.length === 0) {
      for (const i of row.issues) {
        if (skippedByLoader(i, l.warnings) || l.warnings.some((w) => namesPointer(w, i.pointer))) continue;
        const where = (i.pointer || '(document)').replace(/\/\d+/g, '/N');
        increment(silent, `${i.code} at ${where}`, 'accepted');
      }
    }
    if (hostile.length > 0) {
      mustRejectFiles++;
      const found = [...new Set(hostile.map((i) => `${i.code} at ${i.pointer || '(document)'}`))];
      if (!rejected) {
        failures.push(`${row.name}: loaded, but the validator reports ${found.slice(0, 3).join(', ')}${found.length > 3 ? ', ...' : ''}`);
      } else if ([...hostile.map((i) => i.pointer), ...row.pointers].some((p) => namesPointer(message, p))) {
        mustRejectNamed++;
      } else if (verbose) {
        console.log(`not named: ${row.name}: ${hostile[0].code} at ${hostile[0].pointer} vs ${message}`);
      }
    }
  }

  const pct = (a, b) => (b ? (100 * a / b).toFixed(1) : '100.0') + '%';
  console.log(`files: ${rows.length}; validator and loader agree (error <=> rejected) on ${agree}: ${pct(agree, rows.length)}`);
  const mustAccepted = failures.filter((f) => f.includes('loaded, but')).length;
  console.log(`must-reject files: ${mustRejectFiles}, rejected: ${mustRejectFiles - mustAccepted}, ` +
              `message names the validator's object: ${mustRejectNamed} (${pct(mustRejectNamed, mustRejectFiles)})`);
  console.log('validator error code: files, loader rejected, loader accepted (* = must reject)');
  for (const [code, e] of [...byCode].sort((a, b) => b[1].accepted - a[1].accepted || a[0].localeCompare(b[0])))
    console.log(`  ${MUST_REJECT.has(code) || code.startsWith('GLB_') ? '*' : ' '} ${code}: ${e.files}, ${e.rejected}, ${e.accepted}`);
  console.log(`valid to the validator, rejected by the loader: ${[...validButRejected.values()].reduce((s, e) => s + e.files, 0)}`);
  for (const [what, e] of [...validButRejected].sort((a, b) => b[1].files - a[1].files)) console.log(`  ${e.files}: ${what}`);
  console.log(`errors loaded without a warning that names them: ${[...silent.values()].reduce((s, e) => s + e.files, 0)}`);
  for (const [what, e] of [...silent].sort((a, b) => b[1].files - a[1].files)) console.log(`  ${e.files}: ${what}`);
  if (reportPath) fs.writeFileSync(reportPath, JSON.stringify(rows, null, 1));
  for (const f of failures) console.log(`FAIL ${f}`);
  console.log(failures.length ? `${failures.length} failures` : 'no failures');
  process.exit(failures.length ? 1 : 0);
}

main().catch((e) => { console.error(e); process.exit(1); });
