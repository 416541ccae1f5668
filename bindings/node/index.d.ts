// Types of the x3dcheck package: the JSON report of `x3dcheck --format json`.

export type Severity = 'error' | 'warning' | 'info' | 'hint';
export type Level = 'fast' | 'standard' | 'deep';

export interface CheckOptions {
  /** The name the scene is reported under; its directory is where x3dcheck.toml is looked
   * up and the deep level reads referenced files (as `--stdin-filename`). */
  path?: string;
  /** fast, standard or deep (default: x3dcheck.toml's, else standard). */
  level?: Level;
  /** Codes, prefixes of codes (`BACK_MATERIAL_`) or `ALL`, in any case. */
  select?: string[];
  ignore?: string[];
  /** An x3dcheck.toml to use instead of the one found from `path`. */
  config?: string;
}

export interface RelatedPlace {
  line: number;
  column: number;
  message: string;
}

export interface Fix {
  title: string;
  applicability: 'safe' | 'unsafe';
  edits: { line: number; column: number; endLine: number; endColumn: number; content: string }[];
}

export interface Diagnostic {
  code: string;
  severity: Severity;
  message: string;
  /** 1-based; columns count Unicode characters. */
  line: number;
  column: number;
  endLine: number;
  endColumn: number;
  /** The structural path: `/X3D/Scene/Shape[0]/Appearance`. */
  path: string;
  /** The ISO/IEC 19775-1 clause. */
  clause: string;
  index?: number;
  indices?: number[];
  value?: string;
  help?: string;
  related?: RelatedPlace[];
  count?: number;
  fix?: Fix;
}

export interface FileReport {
  path: string;
  encoding: 'xml' | 'json' | 'classicvrml' | 'vrml97' | null;
  compressed?: boolean;
  x3dVersion: string | null;
  profile: string | null;
  diagnostics: Diagnostic[];
  truncated: boolean;
  suppressed?: number;
  stats: Record<string, unknown>;
}

export interface Summary {
  files: number;
  errors: number;
  warnings: number;
  infos: number;
  hints: number;
  suppressed?: number;
}

export declare class Report {
  readonly tool: 'x3dcheck';
  readonly version: string;
  /** The input, then the files its Inlines load (deep level). */
  readonly files: FileReport[];
  readonly summary: Summary;
  /** The findings of every file, the input's first. */
  readonly diagnostics: (Diagnostic & { file: string })[];
  /** The command line's JSON report (`x3dcheck --format json`), byte for byte. */
  toJsonText(): string;
}

export interface Rule {
  code: string;
  severity: Severity;
  level: Level;
  versions: string;
  clause: string;
  summary: string;
  /** Markdown. */
  doc: string;
}

/** Checks a scene (a string is checked as UTF-8) on this thread. Throws when nothing could
 * be checked (an unknown code or level, a wrong x3dcheck.toml). */
export declare function check(source: string | Buffer, options?: CheckOptions): Report;
/** `check` on libuv's thread pool, off the event loop. */
export declare function checkAsync(source: string | Buffer, options?: CheckOptions): Promise<Report>;
/** Checks the file at `path` as `x3dcheck PATH` does (`options.path` is ignored). */
export declare function checkFile(path: string, options?: CheckOptions): Report;
/** Every rule, in catalogue order. */
export declare function rules(): Rule[];
