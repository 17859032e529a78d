#!/usr/bin/env node
// A static web server for the exhibit page on 127.0.0.1 (scripts/web.sh):
//   node tests/js/serve.js SITE_DIR [PORT]
'use strict';

const { startServer } = require('./web_support');

const [site, port] = process.argv.slice(2);
if (!site) {
  console.error('usage: serve.js SITE_DIR [PORT]');
  process.exit(2);
}
startServer(site, Number(port || 0)).then(({ url }) => console.log(`serving ${site} on ${url}/`));
