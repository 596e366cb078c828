/**
 * PARPE's reading of input files and XML with source positions: a public API of the core, used
 * by the loader and by every module that reads a file of its own (the simulator's robot
 * configurations and worlds, the servo buses' hardware profiles, the command line's stimulus
 * and sweep files, the IDE's grid), so that all of them share one set of limits and report
 * problems as {@code FILE:LINE:COL}.
 *
 * <ul>
 *   <li>{@link org.parpe.core.xml.InputFiles}: opens an input file (regular files only, size
 *       limit) and reads its text.</li>
 *   <li>{@link org.parpe.core.xml.XmlReader}: a PARSL-style document as an
 *       {@link org.parpe.core.xml.XElement} tree whose attributes and text are
 *       {@link org.parpe.core.xml.XText}s that remember the position of every character.</li>
 *   <li>{@link org.parpe.core.xml.FlatXmlFile}: a small file of one root and attribute-only
 *       children, with the checks its readers share (known and required attributes, numbers).</li>
 *   <li>{@link org.parpe.core.xml.SourceText}: offsets of a text turned into line and column.</li>
 * </ul>
 *
 * The package depends only on {@code diag}, {@code lang} (numbers) and the XML parsers (Woodstox,
 * Jackson's streaming XML); what a PARSL element means is
 * the loader's ({@code org.parpe.core.load}), not this package's.
 */
package org.parpe.core.xml;
