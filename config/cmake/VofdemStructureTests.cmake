# The floors of the source tree (docs/architecture.md): every include points down, the particles know no
# fluid and the fluid knows no particles; and the checker's own self-test, one planted offence per rule.
add_test(NAME structure/include_floors COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/structure/test_include_floors.py ${CMAKE_CURRENT_SOURCE_DIR})
add_test(NAME structure/include_floors_self_test COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/structure/test_include_floors.py --self-test)
set_tests_properties(structure/include_floors structure/include_floors_self_test PROPERTIES LABELS "quick;structure" TIMEOUT 60)
# What the code cites is in the repository: docs/ pages that exist, equation tags with their section, no
# design file from outside (and the checker's self-test).
add_test(NAME structure/doc_citations COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/structure/test_doc_citations.py ${CMAKE_CURRENT_SOURCE_DIR})
add_test(NAME structure/doc_citations_self_test COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/structure/test_doc_citations.py --self-test)
set_tests_properties(structure/doc_citations structure/doc_citations_self_test PROPERTIES LABELS "quick;structure" TIMEOUT 60)
