/**
 * The dock: the part of the side column where the learning tools' panels open (the probe, the plots, the normal
 * matrix's figure, the adaptive tool), stacked in the order they were opened, so that no panel covers the view. The
 * app provides the element; a tool portals its panel into it (nothing while it is not mounted yet).
 */
import { createContext, useContext } from 'react';

export const DockContext = createContext<HTMLElement | null>(null);

/** The dock element, or null before the side column has mounted. */
export function useDock(): HTMLElement | null {
  return useContext(DockContext);
}
