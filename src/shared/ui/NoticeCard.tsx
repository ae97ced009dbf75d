import './NoticeCard.css';

/** Props of NoticeCard: its text, the close button's name and what it does, and the card's own classes. */
export interface NoticeCardProps {
  text: string;
  close: string;
  onClose: () => void;
  className?: string;
}

/** A notice card: the text and a × button named close (its title too). Live regions stay with the caller. */
export function NoticeCard({ text, close, onClose, className }: NoticeCardProps) {
  return (
    <div className={className ? `notice-card ${className}` : 'notice-card'}>
      <p>{text}</p>
      <button type="button" className="notice-close" aria-label={close} title={close} onClick={onClose}>
        <span aria-hidden="true">×</span>
      </button>
    </div>
  );
}
