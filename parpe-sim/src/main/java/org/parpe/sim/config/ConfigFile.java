package org.parpe.sim.config;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.xml.FlatXmlFile;

/**
 * A robot configuration read from its text (an editor's, a builder's): what it reads as, and
 * where its elements are, each place with its {@link org.parpe.core.diag.SourceSpan} so that
 * the edit layer ({@code org.parpe.core.edit}) can change it in place.
 *
 * @param config   the configuration, or null when the text has errors or defines no part yet
 * @param root     where the {@code <robot-config>} element is (with its span), or null when the
 *                 text is not a robot configuration
 * @param elements the root's child elements in document order, each place with its span
 */
public record ConfigFile(RobotConfig config, SourcePos root, List<FlatXmlFile.Element> elements) {

    public ConfigFile {
        elements = List.copyOf(elements);
    }
}
