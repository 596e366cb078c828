/** Generated and auxiliary panels: parameters dialog, control panel, outline, problems, plots. */
package org.parpe.gui.panels;
