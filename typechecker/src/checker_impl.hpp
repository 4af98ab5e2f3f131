#pragma once
// The checker's internal state, shared by the files that implement it:
// annotations.cpp (annotation declarations and annotated types),
// declarations.cpp (scopes, declarations, statements), expressions.cpp,
// calls.cpp (built-in, user and generic calls, constructors), mismatch.cpp
// (type mismatch diagnostics and physics hints).

#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <safegi/diagnostics/codes.hpp>

#include "builtins.hpp"
#include "expansions.hpp"
#include "symbols.hpp"
#include "safegi/typechecker/checker.hpp"
#include "validation.hpp"

namespace safegi::detail {

// The shortest text that reads back as `value` ("0.01", "100.0").
std::string format_number(double value);

// Where an operand's annotation came from, for the notes of a mismatch.
struct Origin {
  SourceRange range;
  std::string text;  // "'L' declared here", "type of 'c' inferred from its initializer"
  bool inferred = false;  // the type is not written at `range`: notes print it
  // What the note prints when not the value's own type: vec4(x, 0.0) points at x's origin.
  std::shared_ptr<const Type> type;
};

struct Value;
// The length of a variable as it was when measured (`float d = length(L)`): L / d is a unit
// direction while L keeps that value (unit_length.cpp, Checker::divided_by_own_length).
struct LengthOf {
  std::string name;          // the vector measured
  SourceRange declared_at;   // which declaration of that name
  unsigned version = 0;      // its Variable::version then
  bool operator==(const LengthOf&) const = default;
};
// A variable as it was at a point of the program (its version then): the vectors a value is
// known to be perpendicular to are held this way (unit_length.cpp, "Orthonormal frames").
using VariableAt = LengthOf;
// An unannotated `const float PI = 3.14159…;` (or 2π, π/2, 1/π …): which quantity π is depends on
// its use — a plain number (πr²), radians, steradians (2π the hemisphere, 4π the sphere) or projected
// steradians (π for the cosine-weighted hemisphere). A product of it with known dimensions is
// `known · X^exponent`, X one of those for `multiple` (k of kπ); a declared target decides X.
struct PiFactor {
  std::string name;      // the constant
  double multiple = 1;   // k of kπ
  int exponent = 1;      // X^exponent: −1 for 1/π constants and for dividing by one
  DimSlot known;         // the rest of the product
};
// dimension_rules.cpp: the quantities kπ can be (X of PiFactor).
bool pi_can_measure(double multiple, const Dimension& x, const DimensionRegistry& registry);
// The PiFactor of `const float name = value;` when value is kπ or 1/(kπ).
std::optional<PiFactor> pi_constant(const std::string& name, double value);
// orientation.cpp: q - p of two points, one of them the shaded one; a ± b of oriented vectors; s * v.
Orientation point_difference_orientation(const Type& a, const Type& b);
Orientation sum_orientation(bool add, Orientation a, Orientation b);
Orientation scaled_orientation(Orientation o, const Value& scale);
// dimension_rules.cpp: k π for k a multiple of 1/4 (π/4 … 16π): a literal that makes a plain number an angle.
bool is_pi_multiple(double value);

// The result of checking an expression.
struct Value {
  Type type;
  SourceRange range;
  bool lvalue = false;
  bool read_only = false;        // const, uniform, in, read-only built-in
  bool zero = false;             // a zero literal (or a constructor of zeros): fits any dimension
  bool literal = false;          // a numeric literal (possibly negated or parenthesised)
  std::optional<double> number;  // its value, for pow's exponent
  std::optional<long long> constant;  // integer constant value, when known
  std::optional<Origin> origin;
  std::string name;              // the variable named, for messages
  // Read-only because it is memory a buffer_reference of this (readonly) block refers to,
  // whatever `name` is (a reference held in a uniform block is read-only, its memory is not).
  const StructInfo* readonly_reference = nullptr;
  bool stage_output = false;     // an `out` of the stage, or a member or component of one
  bool pi_multiple = false;      // a plain number made with a multiple of π (2.0 * PI * u): an angle in radians
  // How many times the value divides by a squared distance written out (d * d of a length; −1 for
  // d * d itself): 1/d² written out may be the solid angle per projected area the inverse-square
  // law gives (inverse_square(d)); where the value is stored, that reading is taken when it fits.
  int inverse_squares = 0;
  std::optional<LengthOf> length_of;  // length(L) of a variable L, or a local that holds it
  // Vectors this one is perpendicular to by construction: cross(a, b) to a and b,
  // x - n * dot(x, n) to n, and normalize() of such a value to the same.
  std::vector<VariableAt> perpendicular_to;
  std::optional<PiFactor> pi_factor;  // of unknown dimension only through an unannotated π constant
  std::optional<SourceRange> w_divided_at;  // a vec4 that was an hpoint until its xyz were divided by its w here
  bool unit_w = false;  // the w of a vec4(p, 1.0) carried by affine maps: exactly 1
  bool homogeneous_w = false;  // the w of an hpoint (`h.w`), which its coordinates are divided by
  // Exactly +1 or -1 without being a literal: `front ? 1.0 : -1.0`, a local holding it. A unit
  // vector times it is still unit (a double-sided material's normal flipped to the viewer).
  bool unit_sign = false;
  bool plane_normal = false;  // cross(a, b) of two vectors of a space: normalize() makes it their plane's normal
  // mat3(t, b, n) with a column of unknown length (a vector, not a direction): "'b' (column 1
  // of the frame)", why the frame is linear rather than rigid.
  std::string non_unit_column;
};

// Exactly +1 or -1: a literal ±1, or a Value::unit_sign.
inline bool is_unit_sign(const Value& v) { return v.unit_sign || (v.literal && v.number && (*v.number == 1.0 || *v.number == -1.0)); }

struct Variable {
  std::string name;
  Type type;
  SourceRange range;
  bool read_only = false;
  bool builtin = false;
  std::optional<long long> constant;
  Origin origin;
  std::optional<double> number;  // a const float/double's value (pow's exponent, int(x) array sizes)
  bool constant_expression = false;  // const with a constant initializer (GLSL 4.60 §4.3.3)
  bool stage_output = false;          // what it holds leaves the stage
  bool zero_start = false;            // an unannotated local that starts at zero: its first value names its type
  bool pi_multiple = false;           // an unannotated float initialised with a multiple of π (Value::pi_multiple)
  int inverse_squares = 0;            // Value::inverse_squares of an unannotated local's initialiser, until written
  std::optional<LengthOf> length_of;  // a float initialised with length(L), until either is written
  std::vector<VariableAt> perpendicular_to;  // Value::perpendicular_to of its initialiser, until written
  bool unit_sign = false;                    // Value::unit_sign of its initialiser, until written
  bool plane_normal = false;                 // Value::plane_normal of its initialiser, until written
  // A float initialised with dot(a, b): a and b as written, until it is written (a written-out reflection
  // 2 n (n·w) - w may name its cosine).
  std::optional<std::pair<std::string, std::string>> dot_of;
  unsigned version = 0;               // how often it may have been written so far (LengthOf::version)
  // An unannotated const float initialised with kπ or 1/(kπ), or an unannotated local initialised with
  // a product with one (until it is written).
  std::optional<PiFactor> pi_constant;
  std::optional<SourceRange> w_divided_at;  // Value::w_divided_at
};

struct Function {
  std::string name;
  std::vector<Type> params;
  std::vector<bool> out_params;    // out or inout: the argument must be writable
  std::vector<bool> inout_params;  // inout: no implicit conversion either way
  // GL_EXT_spirv_intrinsics: spirv_by_reference (the argument is a variable, passed by its pointer)
  // and spirv_literal (the argument is a constant, passed as a literal operand).
  std::vector<bool> by_reference_params;
  std::vector<bool> literal_params;
  Type result;
  std::vector<std::string> dim_params;
  std::vector<std::string> space_params;
  const ast::FunctionDecl* decl = nullptr;
  bool defined = false;
};

// A call's parameters after overload resolution, ready for annotation unification.
struct CallShape {
  std::vector<Type> params;
  Type result;
  const std::vector<std::string>* dim_params = nullptr;
  const std::vector<std::string>* space_params = nullptr;
};

class Checker {
 public:
  Checker(const CheckOptions& options, DiagnosticEngine& diagnostics, CheckResult& result);
  void run(const ast::TranslationUnit& unit);

  // annotations.cpp
  void declare_dimension(const ast::DimensionDecl& d);
  void declare_unit(const ast::UnitDecl& d);
  void declare_space(const ast::SpaceDecl& d);
  std::optional<DimSlot> resolve_dimension(const ast::DimExpr* e);
  // A unit expression (`centimeter`, `kilometer / hour`, `meter^2`; a dimension
  // name stands for its reference unit) as a dimension with unit factors.
  std::optional<Dimension> resolve_unit(const ast::DimExpr* e);
  Type resolve_type(const ast::TypeSpecifier* spec, const std::vector<ast::ArrayDim>* declarator_dims = nullptr);
  Type with_array_dims(Type base, const std::vector<ast::ArrayDim>& outer);
  // `away`, `toward` or `shaded` as an annotation's last argument; false after reporting one that `g` does not take.
  std::optional<Orientation> orientation_word(const ast::Node* arg) const;
  bool orientation_fits(Geometry g, Orientation o, SourceRange where);
  std::optional<long long> array_size(const ast::ArrayDim& dim);

  // declarations.cpp
  void global_decl(const ast::Decl* d);
  void variable_decl(const ast::VariableDecl& d, bool global);
  StructInfo* buffer_reference_type(const std::string& name);  // GL_EXT_buffer_reference, declared once
  void buffer_reference_block(const ast::InterfaceBlockDecl& d);
  Value buffer_reference_constructor(const ast::CallExpr& e, const Value& out, const std::vector<Value>& args);
  bool combined_sampler(const Type& t, const std::vector<Value>& args) const;
  const ast::Qualifier* storage_of_another_stage(const ast::TypeQualifiers& q) const;
  Type builtin_variable_type(std::string_view text) const;  // builtin_variables.def's spelling
  void block_decl(const ast::InterfaceBlockDecl& d);
  void function_decl(const ast::FunctionDecl& d);
  void statement(const ast::Stmt* s);
  void declare_variable(Variable v);
  const Variable* lookup(const std::string& name) const;
  void push_scope() { scopes_.emplace_back(); }
  void pop_scope() { scopes_.pop_back(); }
  void declare_builtin_variables();
  // The stages that have built-in `name` when the current stage does not ("vertex and geometry"), else empty.
  std::string stages_owning_builtin(const std::string& name) const;
  // The extensions that bring built-in variable `name` to the current stage (builtin_variables.def's
  // BUILTIN_VARIABLE_WITH, "GL_A GL_B"), else empty.
  std::string builtin_variable_extensions(const std::string& name) const;
  void record_interface(const ast::TypeQualifiers& q, const std::string& name, const std::string& block, const Type& t,
                        SourceRange range, const ast::Node* decl);

  // expressions.cpp
  Value expr(const ast::Expr* e);
  Value binary(const ast::BinaryExpr& e);
  Value assign(const ast::AssignExpr& e);
  Value unary(const ast::UnaryExpr& e);
  Value member(const ast::MemberExpr& e);
  Value index(const ast::IndexExpr& e);
  Value ternary(const ast::TernaryExpr& e);
  Value literal(const ast::LiteralExpr& e);
  Value identifier(const ast::IdentifierExpr& e);
  Value initializer_list(const ast::InitializerList& e, const Type& expected);
  // conversions.cpp: `e in target`, to a unit or to a space.
  Value convert(const ast::ConvertExpr& e);
  Value convert_unit(const ast::ConvertExpr& e, const Value& v, const Dimension& target);
  Value convert_space(const ast::ConvertExpr& e, const Value& v, const SpaceSlot& target);
  // operators.cpp: the type of `lhs op rhs` for arithmetic, comparison, logical and bit operators.
  std::optional<Value> reference_arithmetic(ast::BinaryOp op, const Value& lhs, const Value& rhs, SourceRange op_range,
                                            SourceRange range);
  bool buffer_reference2(SourceRange where, const std::string& what);  // GL_EXT_buffer_reference2 enabled, else an error
  Value arithmetic(const ast::Node* node, ast::BinaryOp op, const Value& lhs, const Value& rhs, SourceRange op_range,
                   SourceRange range);
  Value geometric_arithmetic(ast::BinaryOp op, const Value& lhs, const Value& rhs, Type shape, SourceRange op_range,
                             SourceRange range);
  Value homogeneous_product(ast::BinaryOp op, const Value& lhs, const Value& rhs, Type shape, SourceRange op_range,
                            SourceRange range);
  void operand_mismatch(const std::string& message, const Value& lhs, const Value& rhs, SourceRange op_range,
                        const std::string& hint, const char* code);
  void condition(const ast::Expr* e);
  // Checks that `value` may be stored into a `target`; reports one error otherwise.
  bool check_assignable(const Type& target, const Value& value, SourceRange target_range, const std::string& target_name,
                        const std::optional<Origin>& target_origin, const char* action);

  // calls.cpp
  Value call(const ast::CallExpr& e);
  Value method_call(const ast::MethodCallExpr& e);
  Value constructor(const ast::CallExpr& e);
  bool cast_keeps_physics(const Type& to, const Value& value);
  // Homogeneous idioms (homogeneous.cpp).
  void remember_affine_part(Type& vec4, const std::vector<Value>& args) const;
  void map_column(Type& column, const Type& map, long long index) const;
  std::optional<Type> affine_part(const Type& vec4, const std::string& swizzle) const;
  std::optional<Value> map_matrix_call(const std::string& name, const std::vector<Value>& args, SourceRange call_range);
  std::optional<Value> homogeneous_application(const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range);
  Value compose_3x3(const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range);
  void carry_inverse_squares(const ast::BinaryExpr& node, const Value& lhs, const Value& rhs, Value& out) const;
  std::optional<DimSlot> inverse_square_reading(const Value& value) const;
  std::optional<Value> inverse_square_as_solid_angle(const Type& target, const Value& value) const;
  bool homogeneous_part_kept(const Value& value, SourceRange target_range, const std::string& target_name);
  // A user function's parameters: homogeneous coordinates without their w for a parameter that is not
  // an hpoint, and a vec4 whose xyz were divided by its w (divided_in_place) for one that is.
  bool homogeneous_parameters(const std::string& callee, const std::vector<Type>& params, const std::vector<Value>& args);
  bool homogeneous_arguments(const std::string& name, const std::vector<Value>& args);
  // `h.xyz /= h.w;`, `h.xyz = h.xyz / h.w;` of an hpoint variable h: from here h is a plain vec4, remembered as divided.
  void divided_in_place(const ast::AssignExpr& e);
  // Interpolated normals and directions (unit_length.cpp).
  void mark_stage_normal(Type& t, const ast::TypeQualifiers& q, bool flat = false) const;
  std::string not_unit_subject(const Value& v) const;
  std::string written_name(const Value& v) const;
  void report_not_unit(const Value& v, const std::string& where);
  bool unit_length_arguments(const std::string& name, const std::vector<Value>& args);
  // A vector of angles (Euler angles) beside a vector of a space in dot, cross, reflect, …
  bool angles_as_vector(const std::string& name, const std::vector<Value>& args);
  bool unit_length_parameters(const std::string& callee, const Function& f, const std::vector<Value>& args);
  bool unit_length_offset(ast::BinaryOp op, const Value& lhs, const Value& rhs);
  // length(L) of a variable whose value is known not to change behind the checker's back.
  std::optional<LengthOf> length_of_variable(const ast::Expr* arg);
  // `L / length(L)`, `L / d` with d that length, `L /= d`: normalize(L) written out, its type.
  std::optional<Value> divided_by_own_length(const ast::Expr* numerator, const Value& lhs, const Value& rhs, SourceRange range);
  // Orthonormal frames: what normalize(), cross() and Gram-Schmidt's x - n * dot(x, n) are
  // perpendicular to, and cross(n, t) of two perpendicular unit vectors as a direction.
  void carry_perpendicular(const ast::CallExpr& e, const std::vector<Value>& args, Value& v);
  void gram_schmidt(const ast::BinaryExpr& e, Value& v);
  // Everything `n` may write (assignments, ++/--, arguments of calls that can write them) gets a new
  // version; a loop's writes are noted on entry, as its next iteration sees them.
  void note_writes(const ast::Node* n);
  void note_write(const ast::Expr* target);
  std::optional<Dimension> frame_cosine(const Type& t) const;
  bool negative_cosine_kept(const std::string& name, const std::vector<Value>& args, SourceRange call_range);
  bool written_reflection_ok(const Value& lhs, const Value& rhs, SourceRange op_range);
  std::string dot_partner(const ast::Expr* product, const std::string& w_text) const;
  void radians_of_pi_multiple(const std::string& name, std::vector<Value>& args) const;
  std::optional<Value> pi_multiple_as_angle(const Type& target, const Value& value) const;
  // `known · X^e` of a product or quotient with an unannotated π constant (PiFactor).
  // false after reporting a sum no quantity π measures makes consistent.
  bool carry_pi_factor(ast::BinaryOp op, const Value& lhs, const Value& rhs, Value& out, SourceRange op_range);
  // A value that is the target's dimension for no quantity its π constant can be: the dimension it has
  // with π read as the likeliest quantity (pi_reading), for the message; nothing when it fits.
  std::optional<DimSlot> pi_factor_misfit(const Type& target, const Value& value) const;
  std::string pi_reading(const PiFactor& pi, const DimSlot& as) const;
  std::optional<DimSlot> conversion_written_out(const Value& a, const DimSlot& da, const Value& b, const DimSlot& db) const;
  std::optional<Type> frame_constructor(const Type& target, const std::vector<Value>& args) const;
  std::optional<Value> affine_sum(ast::BinaryOp op, const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range);
  // An unannotated local reused for another quantity takes the type of what is assigned (expressions.cpp).
  bool rebind_inferred_local(const ast::AssignExpr& e, const Value& lhs, const Value& value);
  bool infer_from_zero(bool global, const Type& declared, const Value& init) const;
  // The source text of an operand, for a hint's code: its name, else its text when that is one short line, else `fallback`.
  std::string operand_text(const Value& v, const std::string& fallback) const;
  std::optional<std::string> literal_sum_hint(const Value& lhs, const Value& rhs) const;
  std::optional<std::string> unnormalized_dot_hint(const Value& v) const;
  Value builtin_call(const ast::CallExpr* node, const std::string& name, const std::vector<Signature>& sigs,
                     std::vector<Value>& args, SourceRange callee_range, SourceRange call_range);
  Value rule_call(const ast::CallExpr* node, const Signature& sig, std::vector<Value>& args, SourceRange call_range);
  Value user_call(const ast::CallExpr& e, const std::vector<Function>& overloads, std::vector<Value>& args);
  // Unifies the arguments' annotations with a resolved call shape; nothing after reporting an error.
  std::optional<Type> unify_call(const std::string& callee, const CallShape& shape, const std::vector<Value>& args,
                                 SourceRange call_range);
  // A point passed to a vector operation (normalize, length, dot, ...): the one error, physics-aware.
  void point_given_for_vector(const std::string& name, const Signature& sig, const std::vector<Value>& args);
  void negated_point(const Value& p, SourceRange range);
  // Operators on maps and geometric values routed through the built-in table (transform, compose).
  std::optional<Value> geometric_operator(const ast::Node* node, const std::string& builtin, const Value& lhs,
                                          const Value& rhs, SourceRange range);

  // validate_*.cpp: what GL drivers reject beyond the type rules (docs/typechecker.md, "Validation").
  // Version-dependent rules run only when CheckOptions::language is set.
  const LanguageLevel* language() const { return options_.language ? &*options_.language : nullptr; }
  // GL_EXT_spirv_intrinsics is enabled: `gl_` names may be declared, spirv_* qualifiers and types used.
  bool spirv_intrinsics() const { return language() && language()->extension_enabled("GL_EXT_spirv_intrinsics"); }
  bool allows(const VersionGate& gate) const;  // true when the language is unknown
  // The compatibility profile's built-ins exist: desktop GLSL before 1.40, `#version 150 compatibility`, or
  // GL_ARB_compatibility (Mesa: 1.40 is core unless the extension is enabled). True when the language is unknown.
  bool compatibility_profile() const;
  void reject(SourceRange where, std::string message, const char* code, std::string hint = {});
  // The part of `e` that makes it not a constant expression (a variable, a user call, an assignment), or nullptr.
  const ast::Expr* non_constant_part(const ast::Expr* e) const;
  void validate_array_size(const ast::ArrayDim& dim, const Value& size);
  void validate_const_initializer(const ast::Declarator& decl, bool global);
  void validate_global_initializer(const ast::Declarator& decl);  // GLSL ES: constant
  // The built-in `name` exists at this version, stage and profile (builtin_availability.def); else one error at `where`.
  bool builtin_available(const std::string& name, SourceRange where, bool function);
  bool memory_model_qualifiers(const ast::TypeQualifiers& q);  // devicecoherent … nonprivate: their extension
  // The extensions glslang asks of an overload once resolved: the memory-model forms (scope and semantics
  // arguments) need GL_KHR_memory_scope_semantics, atomics on floating-point values
  // GL_EXT_shader_atomic_float or _float2 (calls.cpp).
  bool atomic_overload_available(const std::string& name, const std::vector<Value>& args, SourceRange where);
  void validate_variable(const ast::VariableDecl& d, const Type& base, bool global);
  void validate_interface(const ast::VariableDecl& d, const Type& base);  // a global input or output
  void validate_struct_members(const ast::StructDecl& s);
  void validate_builtin_redeclaration(const ast::VariableDecl& d, const ast::Declarator& decl, const Type& type);
  void validate_block(const ast::InterfaceBlockDecl& d, bool layouts = true);
  void validate_qualifier_decl(const ast::QualifierDecl& d, bool global);
  void validate_function(const ast::FunctionDecl& d, const Function& f);
  void validate_precision(const ast::PrecisionDecl& d);
  void validate_stage(const ast::TranslationUnit& unit);  // compute shaders before 4.30
  // Where barrier() (tessellation control) and the fragment shader interlock may be called.
  void validate_call_placement(const ast::CallExpr& e);
  // Counts the control flow around statements (RAII, in statement()).
  struct FlowScope {
    Checker& checker;
    bool counted;
    FlowScope(Checker& c, const ast::Stmt* s);
    ~FlowScope() { checker.validation_.flow_depth -= counted; }
  };
  void validate_switch(const ast::SwitchStmt& s, const Type& selector);  // pushes switches_
  // validate_lvalues.cpp: an assignable `target` that GLSL still forbids writing; false after reporting.
  bool validate_assignment(const ast::Expr* target, const Value& value);
  // validate_layouts.cpp: layout qualifiers by declaration, stage and version; values; block offsets; locations.
  std::optional<long long> layout_value(const ast::LayoutId& id);  // evaluated and checked once
  void validate_layouts(const ast::TypeQualifiers& q, const LayoutSite& site);
  void record_specialization_constant(const ast::TypeQualifiers& q, const ast::Declarator& decl, const Type& t,
                                      const Variable& v);
  void record_work_group_size_ids(const ast::TypeQualifiers& q, SourceRange range);
  void validate_block_layout(const ast::InterfaceBlockDecl& d);   // std140/std430 offsets and alignments
  void validate_global_layouts(const ast::VariableDecl& d);       // after its declarators are typed
  void validate_block_layouts(const ast::InterfaceBlockDecl& d);  // the block, its members, their offsets
  void validate_default_layouts(const ast::QualifierDecl& d);     // `layout(...) in;`
  void validate_case(const ast::CaseLabel& label, const Value& value);

  // subroutines.cpp
  bool subroutine_declaration(const ast::FunctionDecl& d, const Function& f);  // true: `d` declares a subroutine type
  std::optional<Type> subroutine_type(const std::string& name) const;
  // A call through a subroutine uniform (`f(x)`, `f[i](x)`), or nothing when `e` calls no subroutine uniform.
  std::optional<Value> subroutine_call(const ast::CallExpr& e, std::vector<Value>& args);

  std::string member_path(const ast::Expr* target, const std::string& variable) const;  // for messages: `block.member`
  // dimension_rules.cpp: a cosine used as a number or as a component; radians()/degrees() of angles in units.
  bool cosine_as_number(const DimSlot& expected, const DimSlot& found) const;
  DimSlot projected_component(const DimSlot& scale) const;
  std::optional<Value> angle_conversion(const std::string& name, const Value& arg, const Type& result, SourceRange call_range);

  // orientation.cpp: the expression checked at `range`; the same expression oriented the other way, as code.
  const ast::Expr* expression_at(SourceRange range) const;
  std::string reversed_expression(const ast::Expr* e) const;
  std::string orientation_hint(const Value& value, Orientation expected) const;
  // The orientation of a built-in's result; nothing after reporting an away direction passed as GLSL's incident I.
  std::optional<Orientation> builtin_orientation(const std::string& name, const std::vector<Value>& args, SourceRange call_range);

  // mismatch.cpp. Hints read the found value's expression (its factors) when given its range.
  struct ProductFactor {
    std::string name;  // an identifier or member; empty for other expressions
    DimSlot dim;
    int sign = 1;      // 1: a factor, -1: a divisor
    bool unit = false;     // a unit name used as a number (degree, steradian)
    bool literal = false;
  };
  std::vector<ProductFactor> product_factors(SourceRange range) const;
  std::string find_following_locals(const ast::Expr* e, const std::function<std::string(const ast::Node&)>& match,
                                    int depth = 0) const;
  std::string non_unit_dot_operand(const ast::Expr* e) const;
  std::string angle_divided_by_pi(const ast::Expr* e) const;
  std::optional<std::string> angle_fraction_hint(const Value& lhs, const Value& rhs) const;
  std::string physics_hint(const DimSlot& expected, const DimSlot& found, SourceRange found_range = {}) const;
  std::string operand_hint(const DimSlot& left, const DimSlot& right, SourceRange right_range) const;  // a + b, a - b
  std::string lambert_hint() const;
  std::string unit_vector_sum_hint(const Value& lhs, const Value& rhs, const DimSlot& left, const DimSlot& right) const;
  // Two dimensions, at least one with units: the conversion when they measure the same, else the physics hint.
  std::string unit_hint(const Dimension& expected, const Dimension& found, SourceRange found_range = {},
                        const std::string& found_spelling = {}) const;
  // How `x in …` names the unit of `d`: `centimeter`, `(meter^2)`.
  std::string conversion_target(const Dimension& d) const;
  std::string space_hint(const SpaceSlot& expected, const SpaceSlot& found) const;
  std::string normal_matrix_for_direction_hint(const Value& map, const std::string& kind) const;
  std::string kind_mismatch_hint(Geometry expected, Geometry found) const;
  // Why `left * right` does not compose when their spaces do not meet: wrong order, an inverse, or the space needed.
  std::string compose_hint(const Type& left, const Type& right) const;
  std::string name_of_space(const SpaceSlot& s) const { return space_text(s, result_.registry, template_spaces_); }
  void add_origin_note(Diagnostic& d, const Value& v) const;

  // In the program's words; inside a generic function its parameters print by name.
  std::string name_of(const Type& t) const { return type_name(t, result_.registry, template_dims_, template_spaces_); }
  std::string name_of(const Type& t, const CallShape& s) const {
    return type_name(t, result_.registry, s.dim_params, s.space_params);
  }
  Value error_value(SourceRange range) const {
    Value v;
    v.range = range;
    return v;
  }
  void report(Diagnostic d) {
    if (muted_ > 0) return;  // a trial check (rebind_inferred_local)
    if (d.expansion == kNoExpansion)
      d.expansion = expansions_.find(d.range, !written_statements_.empty() ? written_statements_.back()
                                              : current_function_          ? current_function_->decl->range
                                                                           : SourceRange{});
    diagnostics_.report(std::move(d));
  }
  // Names of extension built-ins and types this checker does not model
  // (subgroup*, *ARB/*EXT/*NV, int64_t, f16vec3, ...): left to the driver.
  static bool extension_name(const std::string& name);
  Value record(const ast::Node* node, Value v) {
    result_.types[node] = v.type;
    return v;
  }

  const CheckOptions& options_;
  DiagnosticEngine& diagnostics_;
  CheckResult& result_;
  std::shared_ptr<const BuiltinLibrary> builtins_;  // built after the program's dimension declarations
  std::vector<std::unordered_map<std::string, Variable>> scopes_;
  int muted_ = 0;  // > 0: report() drops diagnostics (a check tried, not made)
  std::unordered_map<std::string, std::vector<Function>> functions_;
  std::unordered_map<std::string, const StructInfo*> structs_;
  // GL_EXT_buffer_reference2: the bytes r + 1 moves a reference of each block type (its size rounded up
  // to its buffer_reference_align, 16 unless given); absent when the size is not known.
  std::unordered_map<const StructInfo*, long long> reference_strides_;
  std::unordered_map<std::string, Function> subroutine_types_;  // `subroutine void T(...);`
  // Template parameters of the function being declared (resolve_type maps their names to generic slots).
  const std::vector<std::string>* template_dims_ = nullptr;
  const std::vector<std::string>* template_spaces_ = nullptr;
  const Function* current_function_ = nullptr;
  int loop_depth_ = 0;
  ExpansionFinder expansions_;
  std::vector<SourceRange> written_statements_;  // enclosing statements not produced by a macro, innermost last
  struct SwitchContext {
    Type selector;
    std::vector<std::pair<long long, SourceRange>> cases;  // values seen so far
  };
  std::vector<SwitchContext> switches_;  // the switch statements being checked, innermost last
  ValidationState validation_;
  SymbolRecorder symbols_;                       // CheckOptions::record_symbols
};

}  // namespace safegi::detail
