package org.parpe.core.text;

/**
 * A key of one bundle: implemented by the enum of that bundle's keys, whose constant names are
 * the keys in the {@code .properties} files.
 */
public interface Key {

    /** The bundle's base name, e.g. {@code org.parpe.core.text.Messages}. */
    String bundle();

    /** The key as written in the bundle (the enum constant's name). */
    String name();

    /** This key's text in the chosen language with {@code args} put in ({@link Message}). */
    default String text(Object... args) {
        return Message.of(this, args).toString();
    }
}
