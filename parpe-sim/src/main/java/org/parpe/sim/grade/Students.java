package org.parpe.sim.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.text.SimMsg;

/**
 * The students of a folder, in name order: each script directly in it is a student handed in as a
 * lone file, each subfolder a student whose script is the one {@code .xml} or {@code .parsl} file
 * in it (or its {@code main.xml} among several). A student's script is confined to its folder
 * (a lone file: to itself); an entry that is a link is not run, and a folder's script that
 * leads out of its folder is refused by the loader. Names are listed, never read: only the
 * child JVMs read scripts.
 */
public final class Students {
    /**
     * One student.
     *
     * @param name     the file or folder name, as handed in
     * @param script   the script, relative to the students' folder (null when there is none)
     * @param root     what the script may read, relative to the students' folder
     * @param problem  why the student cannot be run (""), for example a folder without a script
     */
    public record Student(String name, Path script, Path root, String problem) {
    }

    private Students() {
    }

    /** The students of {@code dir}, sorted by name (hidden entries left out). */
    public static List<Student> of(Path dir) throws IOException {
        List<Student> students = new ArrayList<>();
        for (Path p : list(dir)) {
            String name = p.getFileName().toString();
            if (name.startsWith(".")) {
                continue;
            }
            if (Files.isSymbolicLink(p)) {
                // a link could lead to another student's work as well as out of the folder
                students.add(new Student(name, null, null, SimMsg.GRADE_LINK.text()));
            } else if (Files.isDirectory(p)) {
                students.add(folder(dir, p, name));
            } else if (InputFiles.isScript(p)) {
                students.add(new Student(name, Path.of(name), Path.of(name), ""));
            }
        }
        return students;
    }

    private static Student folder(Path dir, Path folder, String name) throws IOException {
        List<Path> scripts = list(folder).stream().filter(InputFiles::isScript)
                .filter(p -> !p.getFileName().toString().startsWith(".")).toList();
        Path chosen = scripts.size() == 1 ? scripts.get(0)
                : scripts.stream().filter(p -> p.getFileName().toString().equals("main.xml")).findFirst().orElse(null);
        if (chosen == null) {
            return new Student(name, null, null, scripts.isEmpty() ? SimMsg.GRADE_NO_SCRIPT.text()
                    : SimMsg.GRADE_SCRIPTS.text(scripts.size()));
        }
        return new Student(name, dir.relativize(chosen), Path.of(name), "");
    }

    private static List<Path> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.sorted(Comparator.comparing(p -> p.getFileName().toString())).toList();
        }
    }

}
