/** The IDE window: its parts, menus, tool bars, status bar and alarm banner, and the run actions they trigger. */
package org.parpe.gui.app;
