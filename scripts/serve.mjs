// A static file server on a free loopback port, shared by the benchmarks (plain Node) and the tests that serve
// pages of their own (built apps, the docs site): `serveFiles` maps each URL path to a file, `serveFolder` serves
// a folder (a folder's path, `/` included, is its index.html).
import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize, sep } from 'node:path';

/** @type {Record<string, string>} */
const TYPES = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.mjs': 'text/javascript',
  '.css': 'text/css',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.wasm': 'application/wasm',
};

/**
 * @typedef {{ origin: string, url: (path: string) => string, close: () => Promise<void> }} Served
 *   `origin` is `http://127.0.0.1:<port>`; `url(path)` the address of a path on it.
 */

/**
 * Serve files over HTTP on a free port of 127.0.0.1: `fileFor` maps a URL path (decoded) to a file, or undefined
 * for a 404 (as is a file that does not exist).
 * @param {(path: string) => string | undefined} fileFor
 * @returns {Promise<Served>}
 */
export function serveFiles(fileFor) {
  const server = createServer((req, res) => {
    const file = fileFor(decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname));
    if (!file || !existsSync(file) || !statSync(file).isFile()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
    createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const origin = `http://127.0.0.1:${typeof address === 'object' && address ? address.port : 0}`;
      resolve({
        origin,
        url: (path) => `${origin}/${path.replace(/^\//, '')}`,
        close: () => new Promise((done) => server.close(() => done(undefined))),
      });
    });
  });
}

/**
 * Serve the folder `dir`: a path names the file under it, a folder's path its index.html; nothing outside it.
 * @param {string} dir
 * @returns {Promise<Served>}
 */
export function serveFolder(dir) {
  const root = normalize(dir);
  return serveFiles((path) => {
    let file = normalize(join(root, path));
    if (file !== root && !file.startsWith(root + sep)) return undefined;
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    return file;
  });
}
