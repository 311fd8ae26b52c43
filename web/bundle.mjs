// Bundle the viewer's library for pages opened from disk (`make viewer-lib`): three.js (the part that
// three-entry.js names) into one classic script that defines window.PROPULSOR_THREE, with its version
// and licence in its first line, and its licence text beside it.  Run after `npm ci` in this folder.
import { build } from "esbuild";
import { readFileSync, writeFileSync } from "node:fs";

const out = "../src/propulsor/export/web/";
const three = JSON.parse(readFileSync("node_modules/three/package.json", "utf8"));
const banner = `/* three.js ${three.version} (npm "three", r${three.version.split(".")[1]}), MIT licence: ` +
  `three.LICENSE beside this file; https://threejs.org.  Bundled by \`make viewer-lib\` (web/bundle.mjs) ` +
  `with esbuild: OrbitControls, GLTFLoader and the core classes the viewer uses. */`;
await build({
  entryPoints: ["three-entry.js"], bundle: true, minify: true, format: "iife", globalName: "PROPULSOR_THREE",
  target: "es2019", legalComments: "none", banner: { js: banner }, outfile: out + "three.min.js", logLevel: "warning",
});
writeFileSync(out + "three.LICENSE", readFileSync("node_modules/three/LICENSE", "utf8"));
writeFileSync(out + "three.VERSION", three.version + "\n");
console.log(`three.js ${three.version} -> ${out}three.min.js`);
