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

export class EssiViewer extends HTMLElement {
  /** Shows a tape; resolves with its check report once `essi-load` has fired. */
  load(bytes: Bytes, name?: string): Promise<Report>;
  /** The check report of the tape shown (what check() gives); null before a load. */
  readonly report: Report | null;
  /** The frame's window.essikit (docs/viewer.md) once the viewer runs, else null. */
  readonly viewer: Record<string, unknown> | null;
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
