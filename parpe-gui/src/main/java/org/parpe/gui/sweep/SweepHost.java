package org.parpe.gui.sweep;

import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.diag.Diagnostic;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;

/**
 * What the Sweep/Optimise dialog needs from the IDE window.
 *
 * @param shell    the window the dialog belongs to
 * @param editor   the editor whose text is swept and into which the best values are written
 * @param document the editor's text, loaded (as its file: includes are found next to it)
 * @param robot    the robot the IDE's runs use: {@code auto}, a generator, or a configuration file
 * @param world    the world file the IDE's runs use, or null for the flat floor (read when the dialog opens)
 * @param problems shows diagnostics that have a place in the Problems view (UI thread or any)
 */
public record SweepHost(Shell shell, ParslEditor editor, ScriptDocument document, Supplier<String> robot,
                        Supplier<Path> world, Consumer<List<Diagnostic>> problems) {
}
