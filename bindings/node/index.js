// x3dcheck from Node.js: the Rust library (x3dcheck::api, what the command line calls)
// gives the command line's JSON report; this file parses it into a Report.
'use strict';

const native = require('./x3dcheck.node');

class Report {
  constructor(json) {
    const data = JSON.parse(json);
    this.tool = data.tool;
    this.version = data.version;
    this.files = data.files;
    this.summary = data.summary;
    Object.defineProperty(this, '_json', { value: json });
  }

  /** The findings of every file, the input's first, each with the `file` it is in. */
  get diagnostics() {
    return this.files.flatMap((f) => f.diagnostics.map((d) => ({ file: f.path, ...d })));
  }

  /** The command line's JSON report (`x3dcheck --format json`), byte for byte. */
  toJsonText() {
    return this._json;
  }
}

function check(source, options) {
  return new Report(native.checkJson(source, options));
}

async function checkAsync(source, options) {
  return new Report(await native.checkJsonAsync(source, options));
}

function checkFile(path, options) {
  return new Report(native.checkFileJson(path, options));
}

function rules() {
  return JSON.parse(native.rulesJson());
}

module.exports = { Report, check, checkAsync, checkFile, rules };
