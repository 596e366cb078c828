/**
 * The IDE's words in the user's language. {@link org.parpe.gui.text.UiMsg} holds the keys of the
 * bundle {@code org.parpe.gui.text.Ui} ({@code Ui.properties} English, {@code Ui_de},
 * {@code Ui_es}, {@code Ui_ja}, UTF-8): menus, tool bar, status bar, dialogs and window titles of
 * the window, files, hardware, run, grading, editor and help packages (the views of
 * {@code gui.pose}, {@code gui.diagram}, ... have their own bundle). Texts are looked up when a
 * widget is made, in {@link org.parpe.core.text.Lang#current()}, which {@link
 * org.parpe.gui.text.IdeLanguage} chooses once at start-up ({@code --lang}, then the Language
 * preference, then {@code LC_ALL}/{@code LC_MESSAGES}/{@code LANG}); JFace's own button labels
 * come from {@code org/eclipse/jface/messages_*.properties} beside these files. PARSL's element,
 * attribute and function names stay English: they are the file format.
 */
package org.parpe.gui.text;
