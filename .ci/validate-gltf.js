// Validates glTF binaries with the Khronos glTF validator; exits non-zero when any file has an error or a warning.
// Usage: node validate-gltf.js FILE.glb...   (the gltf-validator npm package must be resolvable)
const validator = require('gltf-validator');
const fs = require('fs');

(async () => {
  let failed = 0;
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), { maxIssues: 50 });
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings`);
    for (const m of issues.messages.filter(m => m.severity <= 1).slice(0, 10)) {
      console.log(`  ${m.code}: ${m.message} at ${m.pointer}`);
    }
    if (issues.numErrors > 0 || issues.numWarnings > 0) failed++;
  }
  process.exit(failed > 0 ? 1 : 0);
})();
