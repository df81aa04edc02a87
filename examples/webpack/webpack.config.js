import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const here = fileURLToPath(new URL('.', import.meta.url));

/** Puts index.html beside the bundle, so that dist/ is the whole site. */
class IndexHtml {
  apply(compiler) {
    compiler.hooks.thisCompilation.tap('IndexHtml', (compilation) => {
      compilation.hooks.processAssets.tap('IndexHtml', () => {
        compilation.emitAsset('index.html', new compiler.webpack.sources.RawSource(readFileSync(`${here}index.html`)));
      });
    });
  }
}

// Nothing here is about workers: webpack 5 finds the engine's worker script by itself and emits
// it as a chunk of its own.
export default {
  mode: 'production',
  context: here,
  entry: './main.js',
  output: { path: `${here}dist`, clean: true },
  plugins: [new IndexHtml()],
  // The engine is a few hundred kilobytes: above webpack's advice for a page, expected here.
  performance: { hints: false },
};
