#include "delegate/shading_graph.h"

#include <algorithm>
#include <map>
#include <string>

namespace fluence::delegate {

namespace {

using render::InputBinding;
using render::ShadingNode;

// A node output as read so far: a constant, a source not yet placed in the graph (so that a
// constant can still fold into it), or a node of the graph.
struct Operand {
    enum class Kind { Constant, Source, Node };
    Kind kind = Kind::Constant;
    ConstantValue constant;
    InputBinding source;
    int node = -1;
    int channels = 1;  // of the value
};

Operand constantOperand(const std::vector<float>& v) {
    Operand o;
    o.channels = o.constant.channels = static_cast<int>(v.size());
    for (std::size_t c = 0; c < 4; ++c) o.constant.value[c] = v.size() == 1 ? v[0] : c < v.size() ? v[c] : 0.0f;
    return o;
}

// Whether the constant's authored channels are all equal.
bool isUniform(const ConstantValue& c) {
    return std::all_of(c.value, c.value + c.channels, [&](float x) { return x == c.value[0]; });
}

// Folds a multiplication by `c` into the source; false when it cannot be folded (a colour
// constant times a one-channel source, or a primvar).
bool scaleSource(InputBinding& s, const ConstantValue& c) {
    if (isUniform(c)) {
        s.factor *= c.value[0];
        return true;
    }
    if (!s.texture || s.channels == 1) return false;
    render::TextureDesc& t = *s.texture;
    for (int k = 0; s.firstChannel + k < 4; ++k) {
        const int channel = s.firstChannel + k;
        t.scale[channel] *= c.value[k];
        t.bias[channel] *= c.value[k];
        t.fallback[channel] *= c.value[k];
    }
    return true;
}

// The value type a node definition names (ND_mix_color3_color3 -> color3, ND_multiply_color3FA
// -> color3), "" when it is not one this file evaluates.
std::string valueTypeOf(const std::string& id, const std::string& prefix) {
    std::string type = id.substr(prefix.size());
    type = type.substr(0, type.find('_'));
    if (type.ends_with("FA")) type.resize(type.size() - 2);
    static const char* const types[] = {"float", "color3", "color4", "vector2", "vector3", "vector4"};
    return std::find(std::begin(types), std::end(types), type) != std::end(types) ? type : "";
}

class GraphReader {
public:
    GraphReader(const ShaderInputs& surface, const std::string& inputName, const LeafReader& leaf)
        : surface_(surface), inputName_(inputName), leaf_(leaf) {}

    DrivenValue read(const NodeOutput& root) {
        std::optional<Operand> value = read(root, 0);
        if (!value) return std::monostate{};
        if (value->kind == Operand::Kind::Constant) return value->constant;
        if (value->kind == Operand::Kind::Source) return value->source;
        InputBinding b;
        b.channels = value->channels;
        b.nodes = std::move(nodes_);
        b.sources = std::move(sources_);
        return b;  // the root is the last node: nodes are placed after their operands
    }

private:
    enum class NodeKind { Constant, Multiply, Mix, Leaf };

    static NodeKind kindOf(const std::string& id) {
        if (id.starts_with("ND_constant_") && !valueTypeOf(id, "ND_constant_").empty()) return NodeKind::Constant;
        if (id.starts_with("ND_multiply_") && !valueTypeOf(id, "ND_multiply_").empty()) return NodeKind::Multiply;
        if (id.starts_with("ND_mix_") && !valueTypeOf(id, "ND_mix_").empty()) return NodeKind::Mix;
        return NodeKind::Leaf;
    }

    void warn(const std::string& message) const {
        surface_.warn()(surface_.shader().path,
                        "input '" + inputName_ + "': " + message + "; using the input's own value");
    }

    std::optional<Operand> read(const NodeOutput& output, int depth) {
        if (depth > kMaxGraphDepth) {
            warn("nodes nested deeper than " + std::to_string(kMaxGraphDepth) + " at " + output.shader->path +
                 " (a cycle?)");
            return std::nullopt;
        }
        const std::string key = output.shader->path + "." + output.output;
        if (auto known = read_.find(key); known != read_.end()) return known->second;
        const ShaderInputs node = surface_.node(*output.shader);
        std::optional<Operand> result;
        switch (kindOf(node.id())) {
            case NodeKind::Constant: result = input(node, "value", 0.0f, depth); break;
            case NodeKind::Multiply: result = multiply(node, depth); break;
            case NodeKind::Mix: result = mix(node, depth); break;
            case NodeKind::Leaf:
                if (std::optional<InputBinding> b = leaf_(output)) {
                    result.emplace();
                    result->kind = Operand::Kind::Source;
                    result->channels = b->channels;
                    result->source = std::move(*b);
                }
                break;
        }
        if (result) read_.emplace(key, *result);
        return result;
    }

    // An input of a node: the node it connects to, else its value, else `fallback`.
    std::optional<Operand> input(const ShaderInputs& node, const char* name, float fallback, int depth) {
        if (std::optional<NodeOutput> source = node.connectedNode(name)) return read(*source, depth + 1);
        std::optional<std::vector<float>> v = node.numbers(name);
        if (!v) return constantOperand({fallback});
        if (v->empty() || v->size() > 4) {
            warn(node.shader().path + ".inputs:" + name + " is not a value of one to four components");
            return std::nullopt;
        }
        return constantOperand(*v);
    }

    std::optional<Operand> multiply(const ShaderInputs& node, int depth) {
        std::optional<Operand> a = input(node, "in1", 0.0f, depth), b = input(node, "in2", 1.0f, depth);
        if (!a || !b) return std::nullopt;
        const int channels = std::max(a->channels, b->channels);
        if (a->kind == Operand::Kind::Constant && b->kind == Operand::Kind::Constant) {
            Operand o = *a;
            o.channels = o.constant.channels = channels;
            for (int c = 0; c < 4; ++c) o.constant.value[c] *= b->constant.value[c];
            return o;
        }
        if (b->kind == Operand::Kind::Source) std::swap(a, b);
        if (a->kind == Operand::Kind::Source && b->kind == Operand::Kind::Constant) {
            Operand o = *a;
            if (scaleSource(o.source, b->constant)) {
                o.channels = channels;
                return o;
            }
        }
        return combine(ShadingNode::Op::Multiply, {&*a, &*b}, channels);
    }

    std::optional<Operand> mix(const ShaderInputs& node, int depth) {
        std::optional<Operand> fg = input(node, "fg", 0.0f, depth), bg = input(node, "bg", 0.0f, depth),
                               amount = input(node, "mix", 0.0f, depth);
        if (!fg || !bg || !amount) return std::nullopt;
        const int channels = std::max(fg->channels, bg->channels);
        if (amount->kind == Operand::Kind::Constant && isUniform(amount->constant)) {
            if (amount->constant.value[0] == 0.0f) return bg;
            if (amount->constant.value[0] == 1.0f) return fg;
        }
        const auto constant = [](const std::optional<Operand>& o) { return o->kind == Operand::Kind::Constant; };
        if (constant(fg) && constant(bg) && constant(amount)) {
            Operand o = *fg;
            o.channels = o.constant.channels = channels;
            for (int c = 0; c < 4; ++c) {
                const float m = amount->constant.value[c];
                o.constant.value[c] = bg->constant.value[c] * (1.0f - m) + fg->constant.value[c] * m;
            }
            return o;
        }
        return combine(ShadingNode::Op::Mix, {&*fg, &*bg, &*amount}, channels);
    }

    // A graph node `op` of the operands (placed first).
    std::optional<Operand> combine(ShadingNode::Op op, std::initializer_list<const Operand*> operands, int channels) {
        ShadingNode n;
        n.op = op;
        int k = 0;
        for (const Operand* o : operands) {
            std::optional<int> placed = place(*o);
            if (!placed) return std::nullopt;
            n.operands[k++] = *placed;
        }
        std::optional<int> node = append(n);
        if (!node) return std::nullopt;
        Operand result;
        result.kind = Operand::Kind::Node;
        result.node = *node;
        result.channels = channels;
        return result;
    }

    // The operand's node in the graph, placing it there if it is not a node yet.
    std::optional<int> place(const Operand& o) {
        if (o.kind == Operand::Kind::Node) return o.node;
        ShadingNode n;
        if (o.kind == Operand::Kind::Constant) {
            std::copy(o.constant.value, o.constant.value + 4, n.constant);
        } else {
            n.op = ShadingNode::Op::Source;
            n.source = static_cast<int>(sources_.size());
            sources_.push_back(o.source);
        }
        return append(n);
    }

    std::optional<int> append(const ShadingNode& n) {
        if (nodes_.size() >= render::kMaxShadingNodes) {
            warn("its nodes need more than " + std::to_string(render::kMaxShadingNodes) + " graph nodes");
            return std::nullopt;
        }
        nodes_.push_back(n);
        return static_cast<int>(nodes_.size()) - 1;
    }

    const ShaderInputs& surface_;
    const std::string& inputName_;
    const LeafReader& leaf_;
    std::vector<ShadingNode> nodes_;
    std::vector<InputBinding> sources_;
    std::map<std::string, Operand> read_;  // node outputs already read, by "<prim path>.<output>"
};

}  // namespace

DrivenValue readDrivenValue(const ShaderInputs& surface, const std::string& inputName, const NodeOutput& output,
                            const LeafReader& leaf) {
    return GraphReader(surface, inputName, leaf).read(output);
}

}  // namespace fluence::delegate
