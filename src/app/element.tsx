import './base.css';
import './embedPage.css';
import { StrictMode } from 'react';
import type { Root } from 'react-dom/client';
import { createRoot } from 'react-dom/client';
import type { EmbedBridge, PatchSource } from '../features/share/embedBridge';
import { EmbedLayout } from './EmbedLayout';
import { ErrorBoundary } from './ErrorBoundary';
import type { EmbedValue } from '../features/share/embedMessages';
import { getMessages } from '../shared/i18n/i18n';
import { loadLanguage } from '../shared/i18n/messageModule';
import { initialState } from './initialState';
import type { ParsedUrl } from '../shared/url/url';
import { URL_KEYS } from '../shared/url/urlKeys';
import { cssVariables } from '../shared/theme/tokens';

/**
 * The stylesheets of the widget, put here by the element build (scripts/viteShadowCss.ts) with page-level
 * selectors and viewport units rewritten for a shadow root; the placeholder stays in a dev build.
 */
const ELEMENT_CSS = '__FOURBAR_LAB_CSS__';

/** The element's tag name. */
export const ELEMENT_NAME = 'fourbar-lab';

/** Attributes the element reads: every URL key (r1..r4, t2, br, pd, pa, play, panels, lock, lang, ...). */
export const ELEMENT_ATTRIBUTES: readonly string[] = URL_KEYS.map((k) => k.name);

function hostCss(): string {
  const tokens = Object.entries(cssVariables())
    .map(([name, value]) => `${name}:${value};`)
    .join('');
  // A definite height makes the host the container the rewritten embed layout measures (cqh, @container). The link's
  // notice, fixed over a page's corner elsewhere, sits in the element's own corner (not the course page's).
  return `:host{${tokens}display:block;position:relative;height:520px;max-width:100%;container-type:size;overflow:auto;background:var(--card)}:host([hidden]){display:none}.url-notice{position:absolute}`;
}

/**
 * `<fourbar-lab>`: the embed widget in a shadow root, its state from the attributes (parsed by the URL table,
 * like the embed's query). Changing an attribute later sets that value; `panels` and `lock` change the panels
 * and locks. Fires `change` (a CustomEvent whose detail is the state as URL keys) when the state changes, and
 * keeps the latest in the `state` property. Each element has its own state and solver.
 */
export class FourbarLabElement extends HTMLElement {
  static readonly observedAttributes = ELEMENT_ATTRIBUTES;
  private root: Root | null = null;
  private parsed: ParsedUrl | null = null;
  private listeners = new Set<(patch: Record<string, unknown>, source: PatchSource) => void>();
  private values: Record<string, EmbedValue> | null = null;
  private generation = 0;

  /** The state as URL keys and values (null before the widget first reported it). */
  get state(): Record<string, EmbedValue> | null {
    return this.values;
  }

  connectedCallback(): void {
    if (this.root) return;
    const shadow = this.shadowRoot ?? this.attachShadow({ mode: 'open' });
    shadow.replaceChildren();
    const style = document.createElement('style');
    // The host rule comes last: the page-level rules rewritten to :host (height: 100%, margin) give way to it.
    style.textContent = ELEMENT_CSS + hostCss();
    const container = document.createElement('div');
    container.id = 'root';
    shadow.append(style, container);
    this.parsed = this.parse();
    this.root = createRoot(container);
    // The strings of the element's language load before it first draws (as mount.tsx does for the page), so a
    // zh-TW element never shows English under a menu that says 繁體中文; offline, English stays.
    const locale = this.parsed.state.shell.locale;
    loadLanguage(locale)
      .catch(() => undefined)
      .then(() => this.render());
  }

  disconnectedCallback(): void {
    this.root?.unmount();
    this.root = null;
  }

  attributeChangedCallback(name: string, old: string | null, value: string | null): void {
    if (!this.root || !this.parsed || old === value) return;
    if (name === 'page') {
      // Another page is another widget (its panels, locks and keys): start it afresh from the attributes.
      this.generation += 1;
      this.parsed = this.parse();
      this.render();
    } else if (name === 'panels' || name === 'lock') {
      this.parsed = { ...this.parsed, embed: this.parse().embed };
      this.render();
    } else if (value !== null) {
      for (const listener of this.listeners) listener({ [name]: value }, 'attribute');
    }
  }

  private parse(): ParsedUrl {
    const q = new URLSearchParams();
    for (const name of ELEMENT_ATTRIBUTES) {
      const v = this.getAttribute(name);
      if (v !== null) q.set(name, v);
    }
    const languages = typeof navigator !== 'undefined' ? (navigator.languages ?? [navigator.language]) : [];
    return initialState(q.toString(), languages, null);
  }

  private readonly bridge: EmbedBridge = {
    publish: (values, first) => {
      this.values = values;
      if (!first) this.dispatchEvent(new CustomEvent('change', { detail: values, bubbles: true, composed: true }));
    },
    listen: (onPatch) => {
      this.listeners.add(onPatch);
      return () => this.listeners.delete(onPatch);
    },
  };

  private render(): void {
    const parsed = this.parsed;
    if (!this.root || !parsed) return;
    const reset = () => {
      this.generation += 1;
      this.parsed = this.parse();
      this.render();
    };
    this.root.render(
      <StrictMode>
        <ErrorBoundary key={this.generation} messages={getMessages(parsed.state.shell.locale)} onReset={reset}>
          <EmbedLayout initial={parsed} embed={parsed.embed} bridge={this.bridge} ownsPage={false} />
        </ErrorBoundary>
      </StrictMode>,
    );
  }
}

if (typeof customElements !== 'undefined' && !customElements.get(ELEMENT_NAME))
  customElements.define(ELEMENT_NAME, FourbarLabElement);
