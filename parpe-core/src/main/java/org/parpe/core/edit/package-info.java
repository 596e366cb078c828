/**
 * The one edit layer (public API): every view that changes the text of a script or a robot
 * file goes through it, and nothing outside it finds places in that text or writes elements.
 *
 * <ul>
 * <li>{@link org.parpe.core.edit.Replacement} is the one replacement record, and
 *     {@link org.parpe.core.edit.TextEdit} a set of them that do not overlap: what a view hands
 *     the editor, applied as one Undo step.</li>
 * <li>{@link org.parpe.core.edit.ScriptEdits} finds places by the {@link org.parpe.core.diag.SourceSpan}s
 *     the loader gives every element (set an attribute, put a child first or last, rename or
 *     remove an element), never by patterns over the text or line:column arithmetic; it works on
 *     any XML file the loader reads with spans, not only scripts.</li>
 * <li>{@link org.parpe.core.edit.SectionEdits} adds an element to a section below the root,
 *     writing the section when the file has none, and starts a script in an empty file.</li>
 * <li>{@link org.parpe.core.edit.ElementWriter} writes an element's tag, attributes (escaped)
 *     and indented children; the printer and the recorder write their elements with it too.</li>
 * </ul>
 *
 * Edits with a meaning of their own (a diagram's, the gait-table expansion) live with their
 * views ({@code org.parpe.core.diagram}) and are made of these. No UI or I/O library.
 */
package org.parpe.core.edit;
