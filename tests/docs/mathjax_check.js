// Typeset TeX fragments with a MathJax 3 bundle and report each one that MathJax marks as an
// error.  Usage: node mathjax_check.js MATHJAX_DIR < fragments.json
// fragments.json: [[tex, display], ...]; prints a JSON list of "error: tex" strings.
// The site loads tex-chtml.js, whose TeX input has the same default packages as input/tex.
const fs = require('fs');
const dir = process.argv[2];
const fragments = JSON.parse(fs.readFileSync(0, 'utf8'));
require(dir + '/node-main.js').init({
  loader: {paths: {mathjax: dir}, load: ['input/tex', 'adaptors/liteDOM']},
}).then(async (MathJax) => {
  const errors = [];
  for (const [tex, display] of fragments) {
    let mml;
    try {
      // the promise form lets MathJax load an extension a fragment needs (autoload)
      mml = await MathJax.tex2mmlPromise(tex, {display: display});
    } catch (e) {
      errors.push(`${e.message}: ${tex.slice(0, 120)}`);
      continue;
    }
    const m = mml.match(/data-mjx-error="([^"]*)"/);
    if (m || mml.includes('<merror')) {
      errors.push(`${m ? m[1] : 'merror'}: ${tex.slice(0, 120)}`);
    }
  }
  process.stdout.write(JSON.stringify(errors));
}).catch((e) => { process.stderr.write(String(e)); process.exit(2); });
