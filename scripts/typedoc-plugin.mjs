// typedoc.json's plugin for the API reference.
// - The `notExported` check for every workspace package it documents. Typedoc's own check lets
//   through any type from a package other than the project's, and the project here is the root
//   package.json (`maxgrid-monorepo`), so alone it would pass a World method that returns a type
//   neither @maxgrid/engine nor @maxgrid/scenes exports.
// - An empty icon in each page's head, as the sandbox's pages have, so that a browser does not ask
//   the sandbox's server for a /favicon.ico it does not have (a 404 in the console).
import {
  Application,
  DeclarationReflection,
  JSX,
  ParameterReflection,
  ReflectionKind,
  SignatureReflection,
  TypeParameterReflection,
  makeRecursiveVisitor,
} from 'typedoc';

/** @param {Application} app */
export function load(app) {
  app.renderer.hooks.on('head.end', () => JSX.createElement('link', { rel: 'icon', href: 'data:,' }));
  app.on(Application.EVENT_VALIDATE_PROJECT, (project) => {
    if (!app.options.getValue('validation').notExported) return;
    const intentional = new Set(app.options.getValue('intentionallyNotExported').map((entry) => entry.slice(entry.lastIndexOf(':') + 1)));
    // The packages whose exports these are: the package of each module's members.
    const documented = new Set();
    for (const module of project.getChildrenByKind(ReflectionKind.Module)) {
      for (const child of module.children ?? []) {
        const id = project.getSymbolIdFromReflection(child);
        if (id) documented.add(id.packageName);
      }
    }
    const warned = new Set();
    for (const owner of Object.values(project.reflections)) {
      const visitor = makeRecursiveVisitor({
        reference(type) {
          const id = type.symbolId;
          if (type.reflection || type.externalUrl || type.isIntentionallyBroken() || !id || !documented.has(id.packageName)) return;
          if (intentional.has(type.qualifiedName) || project.symbolIdHasBeenRemoved(id) || warned.has(id.getStableKey())) return;
          warned.add(id.getStableKey());
          app.logger.validationWarning(
            `${type.qualifiedName}, defined in ${id.packageName}/${id.packagePath}, is referenced by ${owner.getFriendlyFullName()} but not exported from its package's entry point`,
          );
        },
      });
      if (owner instanceof DeclarationReflection) {
        owner.type?.visit(visitor);
        owner.implementedTypes?.forEach((type) => type.visit(visitor));
      } else if (owner instanceof SignatureReflection || owner instanceof ParameterReflection) {
        owner.type?.visit(visitor);
      } else if (owner instanceof TypeParameterReflection) {
        owner.type?.visit(visitor);
        owner.default?.visit(visitor);
      }
    }
  });
}
