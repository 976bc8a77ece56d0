// The WebAssembly side of the lab's check (lab/engine/lab_check.cpp is the
// native one): runs the cases of a file through the lab engine the page's
// worker loads (lab-engine.js and .wasm of the build), with the same calls in
// the same order as lab_check, and prints lab_digest() after each case.
//   node check_wasm.js ENGINE_DIR CASES
'use strict';
const fs = require('fs');
const path = require('path');

async function main() {
  const [dir, casesFile] = process.argv.slice(2);
  const createLabEngine = require(path.resolve(dir, 'lab-engine.js'));
  const engine = await createLabEngine({wasmBinary: fs.readFileSync(path.join(dir, 'lab-engine.wasm'))});
  const start = engine.cwrap('lab_start', 'number', ['string', 'number', 'number', 'number', 'number', 'number', 'number']);
  const advance = engine.cwrap('lab_advance', 'number', ['number', 'number', 'number']);
  const message = engine.cwrap('lab_message', 'string', []);
  const digest = engine.cwrap('lab_digest', 'string', []);
  let out = '';
  for (const line of fs.readFileSync(casesFile, 'utf8').split('\n')) {
    if (line === '' || line.startsWith('#')) continue;
    const f = line.trim().split(/\s+/);
    const [scene, N, r, delta, sticky, onLine, seed, tEnd, frames, budget, cells] =
        [f[0], ...f.slice(1).map(Number)];
    out += `case ${line}\n`;
    if (start(scene, N, r, delta, sticky, onLine, seed) !== 0) {
      out += `error ${message()}\n`;
      continue;
    }
    let code = 0, steps = 0;
    for (let k = 1; k <= frames && code !== 2 && code !== -1; ++k) {
      const t = tEnd * k / frames;  // as lab_check: t_end * k / frames in doubles
      do { code = advance(t, budget, cells); ++steps; } while (code === 1);
    }
    out += `steps ${steps} code ${code}\n` + (code === -1 ? message() : digest());
  }
  process.stdout.write(out);
}

main().catch((e) => { console.error(`check_wasm: ${e}`); process.exit(1); });
