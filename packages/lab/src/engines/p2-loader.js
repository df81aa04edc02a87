// Plain JavaScript on purpose; see p2-loader.d.ts.
export const loadP2 = () => import('p2-es');
