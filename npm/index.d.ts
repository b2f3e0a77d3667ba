// essikit's JavaScript API (docs/javascript.md): the `essi` CLI's own code run in memory. The report types are those
// of docs/report-schema.json (the keys `essi check --format json` writes).

/** A tape or a profile file: text (UTF-8), bytes or an ArrayBuffer. */
export type Bytes = string | Uint8Array | ArrayBuffer | ArrayBufferView;

/** A built-in profile name (`profiles()`), `"auto"` (the dialect the tape's codes show), or a profile's JSON. */
export type ProfileOption = string | Record<string, unknown>;

export interface CommonOptions {
  /** `--profile`; default `iso6582`. An object is the content of a JSON profile file. */
  profile?: ProfileOption;
  /** `--input`: `"essi"`, `"eia"` or `"auto"` (from the content; the default). */
  input?: 'essi' | 'eia' | 'auto';
  /** `--lang`: the language of messages; default `"en"`. */
  lang?: 'en' | 'de' | 'zh';
  /** The tape's path as the report shows it; default `"-"` (read as standard input). */
  name?: string;
}

export interface CheckOptions extends CommonOptions {
  /** `--max-diagnostics N` */
  maxDiagnostics?: number;
  /** `--max-per-code N` */
  maxPerCode?: number;
}

export interface TraceOptions extends CommonOptions {
  /** `--decimals N` (0–9; default 3) */
  decimals?: number;
  /** `--kerf`: the torch's kerf-compensated path */
  kerf?: boolean;
  /** `--machine`: machine coordinates */
  machine?: boolean;
}

export interface ConvertOptions extends CommonOptions {
  /** `--to`; default `"essi"`. */
  to?: 'essi' | 'eia' | 'gcode';
  /** `--to-profile`: the dialect written; default the profile it is read with. */
  toProfile?: ProfileOption;
  /** `--absolute` (82, G90); incremental otherwise. */
  absolute?: boolean;
  /** `--force`: write a tape that has errors too. */
  force?: boolean;
}

export interface DiffOptions extends Omit<CommonOptions, 'name'> {
  /** The two tapes' paths as the report shows them; default `["A", "B"]`. */
  names?: [string, string];
}

export interface Diagnostic {
  code: string;
  severity: 'error' | 'warning' | 'note';
  line: number;
  column: number;
  message: string;
  contour?: { first_line: number; last_line: number };
  at?: { x: number; y: number };
  related?: Array<{ line: number; end_line: number; message: string }>;
  overlap?: Array<Array<[number, number]>>;
  [key: string]: unknown;
}

export interface Box {
  min_x: number;
  min_y: number;
  max_x: number;
  max_y: number;
}

export interface Stats {
  blocks: number;
  motions: number;
  pierces: number;
  cut_length_mm: number;
  mark_length_mm: number;
  travel_length_mm: number;
  rapid_length_mm: number;
  estimated_time_s: number;
  cut_bbox_mm: Box | null;
  end_position_mm: { x: number; y: number };
  [key: string]: unknown;
}

export interface FileReport {
  path: string;
  ok: boolean;
  diagnostics: Diagnostic[];
  stats: Stats;
  diagnostics_omitted?: number;
  [key: string]: unknown;
}

/** `essi check --format json` (docs/report-schema.json). */
export interface Report {
  files: FileReport[];
  profile: string;
  summary: { files: number; files_ok: number; errors: number; warnings: number; [key: string]: unknown };
  [key: string]: unknown;
}

/** `essi stats --format json`. */
export interface StatsReport {
  files: Array<{ path: string; stats: Stats }>;
  profile: string;
}

/** `essi diff --format json` (docs/cli.md, essi diff). */
export type DiffReport = Record<string, unknown>;

/** What `run()` gives: the exit code and what the CLI printed. */
export interface RunResult {
  code: number;
  stdout: Uint8Array;
  stderr: string;
}

/** A call the CLI refused: its exit code and the lines it printed on stderr. */
export class EssikitError extends Error {
  readonly exitCode: number;
  readonly stderr: string;
  readonly diagnostics: string[];
}

/** `essi check --format json` of one tape. A tape with errors resolves; its report says so. */
export function check(data: Bytes, options?: CheckOptions): Promise<Report>;
/** `essi stats --format json` of one tape. */
export function stats(data: Bytes, options?: CommonOptions): Promise<StatsReport>;
/** `essi trace`: one record a line. */
export function trace(data: Bytes, options?: TraceOptions): Promise<string>;
/** `essi convert`: the converted tape. Rejects for a tape with errors unless `force`. */
export function convert(data: Bytes, options?: ConvertOptions): Promise<string>;
/** `essi diff --format json A B`. */
export function diff(a: Bytes, b: Bytes, options?: DiffOptions): Promise<DiffReport>;
/** `essi profile list`. */
export function profiles(): Promise<string[]>;
/** The version (`essi --version`; CMake's project(VERSION)). */
export function version(): Promise<string>;
/** The CLI once, in memory: `args` as after `essi`, `files` written first, `stdin` the bytes of `-`. */
export function run(args: Array<string | number>, options?: { files?: Record<string, Bytes>; stdin?: Bytes }): Promise<RunResult>;
