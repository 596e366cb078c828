package org.parpe.cli.hw;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/** A CSV trace read back: header and numeric rows. */
final class Traces {
    final List<String> header;
    final List<double[]> rows = new ArrayList<>();

    Traces(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file);
        header = Arrays.asList(lines.get(0).split(","));
        for (String l : lines.subList(1, lines.size())) {
            rows.add(Arrays.stream(l.split(",")).mapToDouble(Double::parseDouble).toArray());
        }
    }

    int column(String name) {
        int c = header.indexOf(name);
        if (c < 0) {
            throw new AssertionError("no column " + name + " in " + header);
        }
        return c;
    }
}
