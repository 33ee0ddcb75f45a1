#!/usr/bin/env node
// SPDX-License-Identifier: MIT
// A tiny static file server for the scene page: serves the repository (the page imports
// the package from bindings/js), nothing from the network. It makes the page cross-origin
// isolated (the two headers below), which lets the page share memory with Web Workers
// and so run the package's threads build.
//   node examples/web/serve.mjs [port]     then open http://127.0.0.1:<port>/examples/web/
import http from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.css': 'text/css', '.png': 'image/png', '.json': 'application/json',
  '.svg': 'image/svg+xml',
};

export function startServer(port = 0) {
  const server = http.createServer(async (request, response) => {
    try {
      const url = new URL(request.url, 'http://localhost');
      let file = path.normalize(path.join(ROOT, decodeURIComponent(url.pathname)));
      if (file !== ROOT && !file.startsWith(ROOT + path.sep)) {
        response.writeHead(403).end('outside the repository');
        return;
      }
      if ((await stat(file)).isDirectory()) file = path.join(file, 'index.html');
      const body = await readFile(file);
      response.writeHead(200, { 'content-type': TYPES[path.extname(file)] ?? 'application/octet-stream',
                                'cache-control': 'no-store', 'cross-origin-opener-policy': 'same-origin',
                                'cross-origin-embedder-policy': 'require-corp' });
      response.end(body);
    } catch {
      response.writeHead(404).end('not found');  // also a malformed path
    }
  });
  return new Promise((resolve) => server.listen(port, '127.0.0.1', () => resolve(server)));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const server = await startServer(Number(process.argv[2] ?? 8017));
  console.log(`serving http://127.0.0.1:${server.address().port}/examples/web/`);
}
