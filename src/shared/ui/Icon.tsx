/** Names of the inline icons (drawn as SVG so no icon font or emoji glyph is needed). */
export type IconName =
  | 'play'
  | 'pause'
  | 'stepBack'
  | 'stepForward'
  | 'plus'
  | 'minus'
  | 'fit'
  | 'language'
  | 'undo'
  | 'redo'
  | 'save'
  | 'open'
  | 'recent';

const PATHS: Record<IconName, string> = {
  play: 'M5 3.5v9l7.5-4.5z',
  pause: 'M4.5 3.5h2.6v9H4.5zM8.9 3.5h2.6v9H8.9z',
  stepBack: 'M3.5 3.5h1.8v9H3.5zM12.5 3.5v9L6 8z',
  stepForward: 'M10.7 3.5h1.8v9h-1.8zM3.5 3.5v9L10 8z',
  plus: 'M7.2 3h1.6v4.2H13v1.6H8.8V13H7.2V8.8H3V7.2h4.2z',
  minus: 'M3 7.2h10v1.6H3z',
  fit: 'M2.5 2.5h4v1.5H4v2.5H2.5zM9.5 2.5h4v4H12V4H9.5zM2.5 9.5H4V12h2.5v1.5h-4zM12 9.5h1.5v4h-4V12H12z',
  language:
    'M2 3h6v1.3H5.8c-.3 1.6-1 3-2 4.1.6.4 1.3.8 2 1l-.5 1.2c-.9-.3-1.7-.8-2.4-1.3-.7.6-1.5 1-2.4 1.3L0 9.4c.8-.2 1.5-.6 2.1-1-.6-.7-1.1-1.5-1.4-2.3l1.2-.4c.3.6.6 1.2 1.1 1.7.7-.9 1.2-1.9 1.4-3.1H2zm8.7 3h1.5l3 7.5h-1.4l-.7-1.9h-3.3l-.7 1.9H7.7zm.7 1.6-1.2 3h2.4z',
  undo: 'M6 3 2 6.5 6 10V7.75h3.5a2.75 2.75 0 0 1 0 5.5H7v1.5h2.5a4.25 4.25 0 0 0 0-8.5H6z',
  redo: 'M10 3l4 3.5-4 3.5V7.75H6.5a2.75 2.75 0 0 0 0 5.5H9v1.5H6.5a4.25 4.25 0 0 1 0-8.5H10z',
  save: 'M7.25 2h1.5v6.4l2.2-2.2 1.06 1.06L8 11.3 3.99 7.26l1.06-1.06 2.2 2.2zM2.5 12H4v1.5h8V12h1.5v3h-11z',
  open: 'M1.5 3.5h4.3l1.5 1.5h7.2v8.5h-13zM3 6.5V12h10V6.5z',
  recent:
    'M8 1.5a6.5 6.5 0 1 0 0 13 6.5 6.5 0 0 0 0-13zM8 3a5 5 0 1 1 0 10A5 5 0 0 1 8 3zm-.75 1.5h1.5v3.19l2.28 2.28-1.06 1.06-2.72-2.72z',
};

/** Props of Icon: which icon and its size in CSS pixels (default 16). */
export interface IconProps {
  name: IconName;
  size?: number;
}

/** A small decorative SVG icon (aria-hidden: the button around it carries the accessible name). */
export function Icon({ name, size = 16 }: IconProps) {
  return (
    <svg width={size} height={size} viewBox="0 0 16 16" aria-hidden="true" focusable="false" className="icon">
      <path d={PATHS[name]} fill="currentColor" />
    </svg>
  );
}
