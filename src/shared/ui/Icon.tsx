/** Names of the inline icons (drawn as SVG so no icon font or emoji glyph is needed). */
export type IconName = 'play' | 'pause' | 'stepBack' | 'stepForward' | 'plus' | 'minus' | 'fit' | 'language';

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
