/**
 * The tutorial inside the IDE (Help → Tutorial): the lessons of {@code docs/tutorial}, read
 * from their Markdown and shown with their pictures, and a button that opens each lesson's
 * script in the editor.
 */
package org.parpe.gui.help;
