/**
 * A small SVG DOM for drawing the charts in Node (vitest's node environment has no DOM): elements with
 * attributes, text, dataset, tree edits, the selectors the chart kit and d3 use (tag, .class, tag.class,
 * descendant and child combinators, :scope) and an XML serialiser. Enough for d3-selection and d3-axis;
 * layout, style and events are not modelled. installFakeSvgDom() sets document and XMLSerializer globals.
 */

const SVG_NS = 'http://www.w3.org/2000/svg';

class FakeText {
  readonly nodeType = 3;
  parentNode: FakeElement | null = null;
  constructor(
    readonly ownerDocument: FakeDocument,
    public data: string,
  ) {}
  get textContent(): string {
    return this.data;
  }
  cloneNode(): FakeText {
    return new FakeText(this.ownerDocument, this.data);
  }
}

type FakeNode = FakeElement | FakeText;

/** One compound selector (tag and classes) and how it relates to the one before it. */
interface Step {
  combinator: ' ' | '>';
  scope: boolean;
  tag: string | null;
  classes: string[];
}

function parseSelector(selector: string): Step[] {
  const steps: Step[] = [];
  let combinator: ' ' | '>' = ' ';
  for (const token of selector.trim().replace(/>/g, ' > ').split(/\s+/)) {
    if (token === '>') {
      combinator = '>';
      continue;
    }
    if (token === ':scope') {
      steps.push({ combinator, scope: true, tag: null, classes: [] });
    } else {
      const [tag, ...classes] = token.split('.');
      if (/[[:#*]/.test(token)) throw new Error(`fakeSvgDom: unsupported selector ${selector}`);
      steps.push({ combinator, scope: false, tag: tag || null, classes });
    }
    combinator = ' ';
  }
  return steps;
}

function matchesStep(el: FakeElement, step: Step, scope: FakeElement): boolean {
  if (step.scope) return el === scope;
  if (step.tag && el.localName !== step.tag) return false;
  const cls = (el.getAttribute('class') ?? '').split(/\s+/);
  return step.classes.every((c) => cls.includes(c));
}

/** True when el matches steps[0..k] read right to left, ancestors bounded by scope's subtree. */
function matches(el: FakeElement, steps: Step[], k: number, scope: FakeElement): boolean {
  if (!matchesStep(el, steps[k], scope)) return false;
  if (k === 0) return true;
  const comb = steps[k].combinator;
  for (let p = el.parentNode; p; p = p.parentNode) {
    if (matches(p, steps, k - 1, scope)) return true;
    if (comb === '>') return false;
  }
  return false;
}

const escapeXml = (s: string, attr: boolean) =>
  s
    .replace(/&/g, '&amp;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;')
    .replace(/"/g, attr ? '&quot;' : '"');

/** An element: what d3 and the chart kit call on SVG elements. */
export class FakeElement {
  readonly nodeType = 1;
  parentNode: FakeElement | null = null;
  childNodes: FakeNode[] = [];
  readonly attrs = new Map<string, string>();
  readonly style: Record<string, string> = {};
  /** Attribute writes, child insertions and removals on this element (what a MutationObserver would see). */
  writes = 0;
  [key: string]: unknown;
  constructor(
    readonly ownerDocument: FakeDocument,
    readonly namespaceURI: string,
    readonly localName: string,
  ) {}
  get tagName(): string {
    return this.localName;
  }
  get nodeName(): string {
    return this.localName;
  }
  get children(): FakeElement[] {
    return this.childNodes.filter((n): n is FakeElement => n instanceof FakeElement);
  }
  get firstChild(): FakeNode | null {
    return this.childNodes[0] ?? null;
  }
  get nextSibling(): FakeNode | null {
    const sib = this.parentNode?.childNodes ?? [];
    return sib[sib.indexOf(this) + 1] ?? null;
  }
  get ownerSVGElement(): FakeElement | null {
    for (let p = this.parentNode; p; p = p.parentNode) if (p.localName === 'svg') return p;
    return null;
  }
  get textContent(): string {
    return this.childNodes.map((n) => n.textContent).join('');
  }
  set textContent(v: string) {
    this.writes++;
    this.childNodes.forEach((n) => (n.parentNode = null));
    this.childNodes = v === '' ? [] : [new FakeText(this.ownerDocument, String(v))];
    this.childNodes.forEach((n) => (n.parentNode = this));
  }
  get dataset(): Record<string, string> {
    const attrName = (k: string) => `data-${k.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`)}`;
    return new Proxy({} as Record<string, string>, {
      get: (_t, k) => (typeof k === 'string' ? (this.getAttribute(attrName(k)) ?? undefined) : undefined),
      set: (_t, k, v) => {
        this.setAttribute(attrName(String(k)), String(v));
        return true;
      },
    });
  }
  setAttribute(name: string, value: unknown): void {
    this.writes++;
    this.attrs.set(name, String(value));
  }
  getAttribute(name: string): string | null {
    return this.attrs.get(name) ?? null;
  }
  hasAttribute(name: string): boolean {
    return this.attrs.has(name);
  }
  removeAttribute(name: string): void {
    if (this.attrs.delete(name)) this.writes++;
  }
  appendChild<N extends FakeNode>(node: N): N {
    return this.insertBefore(node, null);
  }
  insertBefore<N extends FakeNode>(node: N, ref: FakeNode | null): N {
    node.parentNode?.removeChild(node);
    this.writes++;
    const i = ref ? this.childNodes.indexOf(ref) : -1;
    if (i < 0) this.childNodes.push(node);
    else this.childNodes.splice(i, 0, node);
    node.parentNode = this;
    return node;
  }
  removeChild<N extends FakeNode>(node: N): N {
    const i = this.childNodes.indexOf(node);
    if (i >= 0) this.childNodes.splice(i, 1);
    this.writes++;
    node.parentNode = null;
    return node;
  }
  remove(): void {
    this.parentNode?.removeChild(this);
  }
  /** 4 (following) when other comes after this in document order, else 2 (preceding); what d3's order() asks. */
  compareDocumentPosition(other: FakeElement): number {
    const order = this.ownerDocument.treeOrder(this, other);
    return order < 0 ? 4 : 2;
  }
  querySelectorAll(selector: string): FakeElement[] {
    const steps = parseSelector(selector);
    const out: FakeElement[] = [];
    const walk = (el: FakeElement) => {
      for (const c of el.children) {
        if (matches(c, steps, steps.length - 1, this)) out.push(c);
        walk(c);
      }
    };
    walk(this);
    return out;
  }
  querySelector(selector: string): FakeElement | null {
    return this.querySelectorAll(selector)[0] ?? null;
  }
  cloneNode(deep = false): FakeElement {
    const copy = new FakeElement(this.ownerDocument, this.namespaceURI, this.localName);
    this.attrs.forEach((v, k) => copy.attrs.set(k, v));
    if (deep) for (const c of this.childNodes) copy.appendChild(c.cloneNode(true));
    return copy;
  }
}

/** The document: creates elements and text and knows tree order. */
export class FakeDocument {
  readonly documentElement: FakeElement = new FakeElement(this, 'http://www.w3.org/1999/xhtml', 'html');
  createElementNS(ns: string, name: string): FakeElement {
    return new FakeElement(this, ns, name);
  }
  createElement(name: string): FakeElement {
    return new FakeElement(this, 'http://www.w3.org/1999/xhtml', name);
  }
  createTextNode(data: string): FakeText {
    return new FakeText(this, data);
  }
  /** Negative when a comes before b in document order (ancestors first). */
  treeOrder(a: FakeElement, b: FakeElement): number {
    const path = (n: FakeElement) => {
      const p: FakeElement[] = [];
      for (let x: FakeElement | null = n; x; x = x.parentNode) p.unshift(x);
      return p;
    };
    const pa = path(a);
    const pb = path(b);
    let i = 0;
    while (i < pa.length && i < pb.length && pa[i] === pb[i]) i++;
    if (i === pa.length) return -1;
    if (i === pb.length) return 1;
    const parent = pa[i - 1];
    return parent ? parent.childNodes.indexOf(pa[i]) - parent.childNodes.indexOf(pb[i]) : 0;
  }
}

/** Serialises a fake element as XML (attributes in insertion order, text escaped). */
export class FakeXMLSerializer {
  serializeToString(node: FakeNode): string {
    if (node instanceof FakeText) return escapeXml(node.data, false);
    const attrs = [...node.attrs].map(([k, v]) => ` ${k}="${escapeXml(v, true)}"`).join('');
    const inner = node.childNodes.map((c) => this.serializeToString(c)).join('');
    return inner ? `<${node.localName}${attrs}>${inner}</${node.localName}>` : `<${node.localName}${attrs}/>`;
  }
}

/** Writes to el and everything under it (see FakeElement.writes). */
export function writesUnder(el: Element | null): number {
  const f = el as unknown as FakeElement | null;
  return f ? f.writes + f.children.reduce((n, c) => n + writesUnder(c as unknown as Element), 0) : 0;
}

/** A new detached <svg> element in a new fake document, typed as the charts want it. */
export function fakeSvg(): SVGSVGElement {
  return new FakeDocument().createElementNS(SVG_NS, 'svg') as unknown as SVGSVGElement;
}

/** Sets globalThis.document and XMLSerializer to the fakes (for code that makes its own SVG); returns the undo. */
export function installFakeSvgDom(): () => void {
  const g = globalThis as Record<string, unknown>;
  const before = { document: g.document, XMLSerializer: g.XMLSerializer };
  g.document = new FakeDocument();
  g.XMLSerializer = FakeXMLSerializer;
  return () => {
    g.document = before.document;
    g.XMLSerializer = before.XMLSerializer;
  };
}
