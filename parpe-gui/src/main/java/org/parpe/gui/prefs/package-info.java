/** The IDE's per-user settings and the folder they live in (recent files, window, per-file run choices). */
package org.parpe.gui.prefs;
