package org.parpe.gui.help;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * Which files the tutorial shows: {@code docs/tutorial/index.md}, the numbered lessons and the
 * other pages, each from the language's folder ({@code docs/tutorial/de/}) where it is
 * translated, and a picture in the language's variant ({@code img/NAME-de.png}) where the tests
 * made one. Lessons not translated are shown in English.
 */
final class Lessons {
    private Lessons() {
    }

    /**
     * The pages in {@code lang}: each page of {@link #pages(Path)} from the language's folder
     * ({@code de/01-poses.md}) where it is translated, else the English page, so that the list
     * holds every lesson and a translated index links the others as {@code ../07-parameters.md}.
     */
    static List<Path> pages(Path folder, Locale lang) {
        List<Path> english = pages(folder);
        Path own = folder.resolve(lang.getLanguage());
        if (lang.getLanguage().equals(Locale.ENGLISH.getLanguage()) || !Files.isDirectory(own)) {
            return english;
        }
        return english.stream().map(p -> {
            Path translated = own.resolve(p.getFileName().toString());
            return Files.isRegularFile(translated) ? translated : p;
        }).toList();
    }

    /**
     * The picture to show for a link to {@code linked} ({@code img/01-poses-snake.png}): the one
     * the tests made in {@code lang} ({@code img/01-poses-snake-de.png}, the IDE in German) where
     * it exists, else the linked one.
     */
    static Path picture(Path linked, Locale lang) {
        String name = linked.getFileName().toString();
        int dot = name.lastIndexOf('.');
        if (lang.getLanguage().equals(Locale.ENGLISH.getLanguage()) || dot < 0) {
            return linked;
        }
        Path own = linked.resolveSibling(name.substring(0, dot) + "-" + lang.getLanguage() + name.substring(dot));
        return Files.isRegularFile(own) ? own : linked;
    }

    /** index.md, the numbered lessons in order, then any other page (teachers.md). */
    static List<Path> pages(Path folder) {
        List<Path> all;
        try (Stream<Path> s = Files.list(folder)) {
            all = s.filter(p -> p.getFileName().toString().endsWith(".md")).sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
        List<Path> out = new ArrayList<>();
        all.stream().filter(p -> p.getFileName().toString().equals("index.md")).forEach(out::add);
        all.stream().filter(p -> p.getFileName().toString().matches("\\d+-.*")).forEach(out::add);
        all.stream().filter(p -> !out.contains(p)).forEach(out::add);
        return out;
    }
}
