import type { Locale } from '../../shared/state/appState';
import { messageModule } from '../../shared/i18n/messageModule';
import type { SpatialField } from '../../shared/state/slices/spatialSlice';
import type { SpatialLinkageType, SpatialPreset } from '../../spatial';
import { spatialMessagesEn } from './spatialMessagesEn';
import { spatialMessagesZhTw } from './spatialMessagesZhTw';

/** The spatial page's strings: only this page reads them, so they load with it, both languages together. */
export interface SpatialMessages {
  pageTitle: string;
  pageIntro: string;
  kindLegend: string;
  kindSpherical: string;
  kindRssr: string;
  presetLabel: string;
  presetCustom: string;
  presetNames: Record<SpatialPreset['id'], string>;
  /** Each field's label (its URL key follows in the UI). */
  fieldNames: Record<SpatialField, string>;
  /** A refused field value, naming the field and the text typed. */
  fieldError: (field: string, text: string, range: string) => string;
  notNumber: (field: string, text: string) => string;
  branchLegend: string;
  branchOpen: string;
  branchCrossed: string;
  play: string;
  pause: string;
  stepBack: string;
  stepForward: string;
  /** The 3D view: name, hint, tools, projection, the fallback and the loading note. */
  viewLabel: string;
  viewHint: string;
  resetView: string;
  projectionLegend: string;
  perspective: string;
  orthographic: string;
  zoomIn: string;
  zoomOut: string;
  noWebgl: string;
  noWebglDetail: string;
  viewLoading: string;
  cannotClose: (theta2: string) => string;
  /** Numbers panel: its title, the heading of the values at θ2. */
  numbersSection: string;
  numbersTitle: string;
  typeNames: Record<SpatialLinkageType, string>;
  typeLabel: string;
  inputRange: string;
  fullTurn: string;
  outputSwing: string;
  transmission: string;
  transmissionRange: string;
  /** The input motion the rates are for (ω2, α2 as text). */
  omegaNote: (omega2: string, alpha2: string) => string;
  pinA: string;
  pinB: string;
  pinP: string;
  /** Plots. */
  plotsTitle: string;
  plotTheta4: string;
  plotOmega4: string;
  plotAlpha4: string;
  plotMu: string;
  axisTheta2: string;
  /** Exports and share. */
  exportsTitle: string;
  exportPng: string;
  /** Why the PNG export is off: the 3D view has no WebGL (or is still loading). */
  pngNeedsWebgl: string;
  pngLoading: string;
  exportCsv: string;
  copyLink: string;
  linkCopied: string;
  copyEmbed: string;
  embedCopied: string;
  exportFailed: (why: string) => string;
}

/** The spatial page's strings in every language (both bundled with the page's chunk). */
export const spatialMessages = messageModule<SpatialMessages>(spatialMessagesEn, { 'zh-TW': spatialMessagesZhTw });

/** The spatial page's strings in a language. */
export function spatialMessagesFor(locale: Locale): SpatialMessages {
  return spatialMessages.get(locale);
}
