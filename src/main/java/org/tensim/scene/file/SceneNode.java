package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One value of a scene file with where it was written: a map (keys in file order), a list or a scalar
 * (its text as written, and whether the file gave it as a number, a boolean or a string). Every node knows its
 * key path ({@code bodies.liver.material.E}, {@code conditions[2].region}) and its place ({@code file:line:column},
 * or the {@code --set} that gave it), so that every refusal can name both ({@link SceneException}).
 */
public final class SceneNode {
    /** What a node holds. */
    public enum Kind { MAP, LIST, SCALAR, NULL }

    /** How the file wrote a scalar: YAML/JSON numbers, booleans and strings are told apart. */
    public enum Token { NUMBER, BOOLEAN, STRING, NONE }

    private final Kind kind;
    private final Token token;
    private final String text;
    private final String where;
    private final String path;
    private final Map<String, SceneNode> map;
    private final List<SceneNode> list;
    private final Map<String, String> keyWhere;
    /** The kind of quantity the loader read this scalar as (null: not read as a quantity). */
    private QuantityKind readAs;

    private SceneNode(Kind kind, Token token, String text, String where, String path) {
        this.kind = kind;
        this.token = token;
        this.text = text;
        this.where = where;
        this.path = path;
        this.map = kind == Kind.MAP ? new LinkedHashMap<>() : null;
        this.list = kind == Kind.LIST ? new ArrayList<>() : null;
        this.keyWhere = kind == Kind.MAP ? new LinkedHashMap<>() : null;
    }

    static SceneNode map(String where, String path) {
        return new SceneNode(Kind.MAP, Token.NONE, null, where, path);
    }

    static SceneNode list(String where, String path) {
        return new SceneNode(Kind.LIST, Token.NONE, null, where, path);
    }

    static SceneNode scalar(Token token, String text, String where, String path) {
        return new SceneNode(token == Token.NONE ? Kind.NULL : Kind.SCALAR, token, text, where, path);
    }

    public Kind kind() {
        return kind;
    }

    public Token token() {
        return token;
    }

    /** A scalar's text as written (null for maps, lists and null). */
    public String text() {
        return text;
    }

    /**
     * The kind of quantity the loader read this scalar as ({@link SceneUnits#si}), or null when it was not read as
     * one: named parameters take their dimension from it, so that a parameter's unit is checked against what the
     * key really is.
     */
    public QuantityKind readAs() {
        return readAs;
    }

    void markRead(QuantityKind kind) {
        readAs = kind;
    }

    /** {@code file:line:column}, or the {@code --set} option that gave the value. */
    public String where() {
        return where;
    }

    /** The key path from the top of the file, e.g. {@code bodies.mss.stiffness}; "" for the top. */
    public String path() {
        return path;
    }

    /** The path, or "(top level)" for the file itself. */
    public String shownPath() {
        return path.isEmpty() ? "(top level)" : path;
    }

    public boolean isMap() {
        return kind == Kind.MAP;
    }

    public boolean isList() {
        return kind == Kind.LIST;
    }

    public boolean isScalar() {
        return kind == Kind.SCALAR;
    }

    /** Removes a map's key and its value (nothing when absent). */
    void remove(String key) {
        if (map != null) {
            map.remove(key);
            keyWhere.remove(key);
        }
    }

    /** A map's entries in file order (read-only); empty for other kinds. */
    public Map<String, SceneNode> entries() {
        return map == null ? Map.of() : Collections.unmodifiableMap(map);
    }

    /** A map's value of {@code key}, or null. */
    public SceneNode get(String key) {
        return map == null ? null : map.get(key);
    }

    /** A list's items (read-only); empty for other kinds. */
    public List<SceneNode> items() {
        return list == null ? List.of() : Collections.unmodifiableList(list);
    }

    void put(String key, SceneNode value) {
        put(key, value, value.where());
    }

    void put(String key, SceneNode value, String keyPlace) {
        map.put(key, value);
        keyWhere.put(key, keyPlace);
    }

    /** Where a map's key is written (its value's place for keys given by --set); null if there is no such key. */
    public String keyWhere(String key) {
        return keyWhere == null ? null : keyWhere.get(key);
    }

    void set(int index, SceneNode value) {
        list.set(index, value);
    }

    void add(SceneNode value) {
        list.add(value);
    }

    /** The path of a child key. */
    static String child(String path, String key) {
        return path.isEmpty() ? key : path + "." + key;
    }

    /** What the node is, for messages: "a map", "a list", the scalar's text in quotes, or "nothing". */
    public String describe() {
        switch (kind) {
            case MAP:
                return "a map";
            case LIST:
                return "a list";
            case NULL:
                return "nothing (null)";
            default:
                return "\"" + text + "\"";
        }
    }
}
