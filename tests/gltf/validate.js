// validate.js: runs the Khronos glTF Validator (npm gltf-validator) over files.
// Usage: node validate.js FILE.glb|FILE.gltf ...   (NODE_PATH must reach gltf-validator)
// Prints one line per file: "FILE: N errors, N warnings" and each error's code, message and JSON
// pointer, then each warning and info; exits 1 if any file has an error (warnings and infos are
// printed, not failures).
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
  const data = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(data, {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, bytes) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(bytes)));
      }),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos`);
  for (const m of issues.messages)
    if (m.severity <= 2)
      console.log(`  ${['error', 'warning', 'info'][m.severity]} ${m.code}: ${m.message} (${m.pointer || ''})`);
  return issues.numErrors;
}

(async () => {
  let errors = 0;
  for (const file of process.argv.slice(2)) {
    try {
      errors += await validate(file);
    } catch (e) {
      console.log(`${file}: validator failed: ${e}`);
      errors += 1;
    }
  }
  process.exit(errors > 0 ? 1 : 0);
})();
