// Differentiates a muParser expression by re-evaluating its bytecode with Taylor2
// scalars (Griewank & Walther 2008, ch. 13). The bytecode's reverse Polish notation is
// muParser 2.3's (muParserBytecode.h, ParserBase::ParseCmdCodeBulk): a stack machine
// whose stack starts at index 1.
#include "app/case/taylor_evaluation.hpp"

#include <muParser.h>

#include <stdexcept>

#include "app/case/case_functions.hpp"
#include "app/case/expression.hpp"

namespace heavesim {

DifferentiableExpression::DifferentiableExpression(const std::string& text, const std::vector<std::string>& variables,
                                                   const std::map<std::string, double>& parameters)
    : text_(text),
      parser_(std::make_unique<mu::Parser>()),
      parameters_(parameters),
      variable_values_(std::make_unique<double[]>(variables.size())),
      variable_count_(static_cast<int>(variables.size())) {
  define_case_functions(*parser_);
  // Without the optimizer the bytecode holds only the plain codes (no cmVARMUL,
  // cmVARPOW2..4 and no folded constants): each operation as written.
  parser_->EnableOptimizer(false);
  try {  // a mu::ParserError is no std::exception: past here it would end the program
    for (int k = 0; k < variable_count_; ++k) parser_->DefineVar(variables[k], &variable_values_[k]);
    for (auto& [name, value] : parameters_) parser_->DefineVar(name, &value);
    parser_->SetExpr(text);
    // GetUsedVar parses, collecting the variables read, and drops the bytecode; Eval
    // compiles it again (and finds what only evaluation finds, e.g. too few arguments).
    const mu::varmap_type used = parser_->GetUsedVar();
    for (const std::string& name : variables) reads_.push_back(used.count(name) > 0);
    parser_->Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument(parser_error_text(e, text));
  }
  if (parser_->GetNumResults() != 1)
    throw std::invalid_argument("several comma-separated results; an expression has one");
  const mu::ParserByteCode& bytecode = parser_->GetByteCode();
  const mu::SToken* base = bytecode.GetBase();
  bytecode_.assign(base, base + bytecode.GetSize());
  for (const mu::SToken& token : bytecode_) {
    if (token.Cmd == mu::cmASSIGN) throw std::invalid_argument("an assignment ('='); an expression only reads names");
    const bool known = token.Cmd <= mu::cmVAL || token.Cmd == mu::cmFUNC || token.Cmd == mu::cmEND;
    if (!known) throw std::logic_error("case expression: unexpected muParser bytecode " + std::to_string(token.Cmd));
  }
  stack_.resize(bytecode.GetMaxStackSize() + 1);
}

DifferentiableExpression::~DifferentiableExpression() = default;

double DifferentiableExpression::value(const double* variables) const {
  for (int k = 0; k < variable_count_; ++k) variable_values_[k] = variables[k];
  return parser_->Eval();
}

Taylor2 DifferentiableExpression::operand(const mu::SToken& token, const Taylor2* variables) const {
  const double* address = token.Val.ptr;
  const std::ptrdiff_t index = address - variable_values_.get();
  if (index >= 0 && index < variable_count_) return variables[index];
  return Taylor2(*address);  // a case parameter: a constant
}

namespace {

/// The function a cmFUNC token calls, by the addresses of case_functions.hpp.
Taylor2 apply_function(const mu::SToken& token, const Taylor2* args, int count) {
  const mu::generic_callable_type& callable = token.Fun.cb;
  if (callable._pUserData == nullptr) {
    if (callable._pRawFun == reinterpret_cast<mu::erased_fun_type>(&case_unary_minus)) return -args[0];
    if (callable._pRawFun == reinterpret_cast<mu::erased_fun_type>(&case_unary_plus)) return args[0];
  } else {
    for (auto* known : {reinterpret_cast<mu::erased_fun_type>(&call_case_function_1),
                        reinterpret_cast<mu::erased_fun_type>(&call_case_function_2),
                        reinterpret_cast<mu::erased_fun_type>(&call_case_function_3),
                        reinterpret_cast<mu::erased_fun_type>(&call_case_function_5),
                        reinterpret_cast<mu::erased_fun_type>(&call_case_function_n)})
      if (callable._pRawFun == known)
        return apply_case_function(static_cast<const CaseFunctionEntry*>(callable._pUserData)->function, args, count);
  }
  throw std::logic_error("case expression: a function without a derivative rule");
}

Taylor2 truth(bool condition) { return Taylor2(condition ? 1.0 : 0.0); }

}  // namespace

Taylor2 DifferentiableExpression::evaluate(const Taylor2* variables) const {
  Taylor2* stack = stack_.data();
  int top = 0;  // muParser's stack starts at 1
  // A binary operation replaces the two topmost entries by its result.
  auto binary = [&](auto operation) {
    --top;
    stack[top] = operation(stack[top], stack[top + 1]);
  };
  for (const mu::SToken* token = bytecode_.data(); token->Cmd != mu::cmEND; ++token) {
    switch (token->Cmd) {
      // Comparisons and logic: piecewise constant, derivatives 0.
      case mu::cmLE: binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value <= b.value); }); break;
      case mu::cmGE: binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value >= b.value); }); break;
      case mu::cmNEQ: binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value != b.value); }); break;
      case mu::cmEQ: binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value == b.value); }); break;
      case mu::cmLT: binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value < b.value); }); break;
      case mu::cmGT: binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value > b.value); }); break;
      case mu::cmLAND:
        binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value != 0.0 && b.value != 0.0); });
        break;
      case mu::cmLOR:
        binary([](const Taylor2& a, const Taylor2& b) { return truth(a.value != 0.0 || b.value != 0.0); });
        break;
      case mu::cmADD: binary([](const Taylor2& a, const Taylor2& b) { return a + b; }); break;
      case mu::cmSUB: binary([](const Taylor2& a, const Taylor2& b) { return a - b; }); break;
      case mu::cmMUL: binary([](const Taylor2& a, const Taylor2& b) { return a * b; }); break;
      case mu::cmDIV: binary([](const Taylor2& a, const Taylor2& b) { return a / b; }); break;
      case mu::cmPOW: binary([](const Taylor2& a, const Taylor2& b) { return pow(a, b); }); break;
      // c ? a : b -- the branch taken is the one whose derivatives count.
      case mu::cmIF:
        if (stack[top--].value == 0.0) token += token->Oprt.offset;
        break;
      case mu::cmELSE: token += token->Oprt.offset; break;
      case mu::cmENDIF: break;
      case mu::cmVAR: stack[++top] = operand(*token, variables); break;
      case mu::cmVAL: stack[++top] = Taylor2(token->Val.data2); break;
      case mu::cmFUNC: {
        const int count = token->Fun.argc < 0 ? -token->Fun.argc : token->Fun.argc;  // < 0: any number
        top -= count - 1;
        stack[top] = apply_function(*token, &stack[top], count);
        break;
      }
      default: throw std::logic_error("case expression: unexpected muParser bytecode");
    }
  }
  return stack[1];
}

}  // namespace heavesim
