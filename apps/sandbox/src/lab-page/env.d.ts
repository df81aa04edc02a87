// Vite's `?url` imports, declared here so the page type-checks without vite/client types.
declare module '*?url' {
  const url: string;
  export default url;
}
