/** The PARSL editor: colouring, content assist, live validation and error markers. */
package org.parpe.gui.editor;
