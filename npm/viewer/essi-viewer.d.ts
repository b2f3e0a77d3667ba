// <essi-viewer> (docs/viewer-element.md): import 'essikit/viewer' defines the element.
import type { Bytes, Report } from '../index.js';

/** detail of `essi-load`: the tape shown and its check report's summary. */
export interface EssiLoadDetail {
  name: string;
  ok: boolean;
  profile: string;
  summary: Report['summary'];
}

/** detail of `essi-select`: the selected source line and motion (null: none). */
export interface EssiSelectDetail {
  line: number | null;
  motion: number | null;
}

/** The viewer's automation API in the frame (window.essikit, docs/viewer.md): the calls used most; the rest as there. */
export interface ViewerApi {
  ready: Promise<void>;
  state(): Record<string, any>;
  load(name: string, data: string | Uint8Array | ArrayBuffer): Promise<Record<string, any>>;
  idle(timeoutMs?: number): Promise<Record<string, any>>;
  motion(index: number): Record<string, any>;
  selectLine(line: number): void;
  setView(x: number, y: number, zoom: number): void;
  setProfile(name: string): Promise<Record<string, any>>;
  setLanguage(code: string): void;
  setTheme(name: 'light' | 'dark'): void;
  exportText(format: string): string;
  [call: string]: unknown;
}

export class EssiViewer extends HTMLElement {
  /** Shows a tape; resolves with its check report once `essi-load` has fired. */
  load(bytes: Bytes, name?: string): Promise<Report>;
  /** The check report of the tape shown (what check() gives); null before a load. */
  readonly report: Report | null;
  /** The frame's window.essikit (docs/viewer.md) once the viewer runs, else null. */
  readonly viewer: ViewerApi | null;
}

declare global {
  interface HTMLElementTagNameMap {
    'essi-viewer': EssiViewer;
  }
  interface HTMLElementEventMap {
    'essi-load': CustomEvent<EssiLoadDetail>;
    'essi-select': CustomEvent<EssiSelectDetail>;
    'essi-error': CustomEvent<{ message: string }>;
  }
}
