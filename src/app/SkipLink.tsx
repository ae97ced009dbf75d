import './SkipLink.css';

/** Props of SkipLink: the id of the element to jump to and the link's text. */
export interface SkipLinkProps {
  targetId: string;
  label: string;
}

/** A link, shown only when focused, that moves focus to the main content (WCAG 2.4.1 bypass blocks). */
export function SkipLink({ targetId, label }: SkipLinkProps) {
  return (
    <a
      className="skip-link"
      href={`#${targetId}`}
      onClick={(e) => {
        const target = document.getElementById(targetId);
        if (!target) return;
        // Focus without putting the fragment in the address bar (the URL carries the shared state).
        e.preventDefault();
        target.focus();
      }}
    >
      {label}
    </a>
  );
}
